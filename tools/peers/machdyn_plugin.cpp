// LAMMPS plugin registration for the Smooth Mach Dynamics package (MACHDYN, formerly USER-SMD), compiled by
// tools/peers/build_machdyn.sh together with src/MACHDYN/*.cpp of the Debian source package of lammps and
// src/PLUGIN/plugin.cpp, against Debian's liblammps (same version), into build/peers/machdynplugin.so.
//
// Modelled on LAMMPS's examples/plugins/*plugin.cpp: lammpsplugin_init() fills one lammpsplugin_t
// (lammpsplugin.h) per style and hands it to the host's registration callback. Every style MACHDYN defines is
// listed in STYLES below (the build script checks the list against the *Style(...) macros of src/MACHDYN/*.h).
//
// Two details of this LAMMPS version (29 Sep 2021 update 2, Debian 20220106):
// * Its plugin loader (src/PLUGIN/plugin.cpp) knows pair, bond, angle, dihedral, improper, compute, fix, region
//   and command styles, but not atom styles. lammpsplugin_init() therefore enters the atom style "smd"
//   directly into the host's Atom::avec_map and hands the others to the callback.
// * Debian's liblammps/lmp is built without the PLUGIN package, so it has no `plugin` command. This library
//   also contains that command (src/PLUGIN/plugin.cpp compiled with -DLMP_PLUGIN) and exports
//     extern "C" int machdyn_enable_plugin_command(void *lmp)
//   which adds `plugin` to the instance's command table (if absent); then `plugin load <this .so>` works as in
//   a PLUGIN-enabled LAMMPS. The inputs in tools/peers call it through Debian lmp's PYTHON package (ctypes).
//   Alternatively extern "C" int machdyn_register(void *lmp) enters all styles directly, without the command.

#include "lammpsplugin.h"
#include "version.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "utils.h"

#include "plugin.h"    // src/PLUGIN: class Plugin (the `plugin` command)

#include "atom_vec_smd.h"
#include "compute_smd_contact_radius.h"
#include "compute_smd_damage.h"
#include "compute_smd_hourglass_error.h"
#include "compute_smd_internal_energy.h"
#include "compute_smd_plastic_strain.h"
#include "compute_smd_plastic_strain_rate.h"
#include "compute_smd_rho.h"
#include "compute_smd_tlsph_defgrad.h"
#include "compute_smd_tlsph_dt.h"
#include "compute_smd_tlsph_num_neighs.h"
#include "compute_smd_tlsph_shape.h"
#include "compute_smd_tlsph_strain.h"
#include "compute_smd_tlsph_strain_rate.h"
#include "compute_smd_tlsph_stress.h"
#include "compute_smd_triangle_vertices.h"
#include "compute_smd_ulsph_effm.h"
#include "compute_smd_ulsph_num_neighs.h"
#include "compute_smd_ulsph_strain.h"
#include "compute_smd_ulsph_strain_rate.h"
#include "compute_smd_ulsph_stress.h"
#include "compute_smd_vol.h"
#include "fix_smd_adjust_dt.h"
#include "fix_smd_integrate_tlsph.h"
#include "fix_smd_integrate_ulsph.h"
#include "fix_smd_move_triangulated_surface.h"
#include "fix_smd_setvel.h"
#include "fix_smd_tlsph_reference_configuration.h"
#include "fix_smd_wall_surface.h"
#include "pair_smd_hertz.h"
#include "pair_smd_tlsph.h"
#include "pair_smd_triangulated_surface.h"
#include "pair_smd_ulsph.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {

template <class T> AtomVec *atom_creator(LAMMPS *lmp) { return new T(lmp); }
template <class T> Pair *pair_creator(LAMMPS *lmp) { return new T(lmp); }
template <class T> Fix *fix_creator(LAMMPS *lmp, int narg, char **arg) { return new T(lmp, narg, arg); }
template <class T> Compute *compute_creator(LAMMPS *lmp, int narg, char **arg) { return new T(lmp, narg, arg); }
template <class T> Command *command_creator(LAMMPS *lmp) { return new T(lmp); }

struct Style {
  const char *style;    // lammpsplugin_t::style: "atom", "pair", "fix", "compute"
  const char *name;
  const char *cls;
  lammpsplugin_factory1 *v1;    // atom, pair: T *(*)(LAMMPS *)
  lammpsplugin_factory2 *v2;    // fix, compute: T *(*)(LAMMPS *, int, char **)
};

#define V1(f) reinterpret_cast<lammpsplugin_factory1 *>(f)
#define V2(f) reinterpret_cast<lammpsplugin_factory2 *>(f)
#define machdyn_style_atom(name, cls) {"atom", name, #cls, V1(&atom_creator<cls>), nullptr}
#define machdyn_style_pair(name, cls) {"pair", name, #cls, V1(&pair_creator<cls>), nullptr}
#define machdyn_style_fix(name, cls) {"fix", name, #cls, nullptr, V2(&fix_creator<cls>)}
#define machdyn_style_compute(name, cls) {"compute", name, #cls, nullptr, V2(&compute_creator<cls>)}
#define machdyn_style(kind, name, cls) machdyn_style_##kind(name, cls)

const Style STYLES[] = {
    machdyn_style(atom, "smd", AtomVecSMD),

    machdyn_style(pair, "smd/hertz", PairHertz),
    machdyn_style(pair, "smd/tlsph", PairTlsph),
    machdyn_style(pair, "smd/tri_surface", PairTriSurf),
    machdyn_style(pair, "smd/ulsph", PairULSPH),

    machdyn_style(fix, "smd/adjust_dt", FixSMDTlsphDtReset),
    machdyn_style(fix, "smd/integrate_tlsph", FixSMDIntegrateTlsph),
    machdyn_style(fix, "smd/integrate_ulsph", FixSMDIntegrateUlsph),
    machdyn_style(fix, "smd/move_tri_surf", FixSMDMoveTriSurf),
    machdyn_style(fix, "smd/setvel", FixSMDSetVel),
    // internal fix that pair smd/tlsph creates itself (modify->add_fix) to hold the reference configuration
    machdyn_style(fix, "SMD_TLSPH_NEIGHBORS", FixSMD_TLSPH_ReferenceConfiguration),
    machdyn_style(fix, "smd/wall_surface", FixSMDWallSurface),

    machdyn_style(compute, "smd/contact/radius", ComputeSMDContactRadius),
    machdyn_style(compute, "smd/damage", ComputeSMDDamage),
    machdyn_style(compute, "smd/hourglass/error", ComputeSMDHourglassError),
    machdyn_style(compute, "smd/internal/energy", ComputeSMDInternalEnergy),
    machdyn_style(compute, "smd/plastic/strain", ComputeSMDPlasticStrain),
    machdyn_style(compute, "smd/plastic/strain/rate", ComputeSMDPlasticStrainRate),
    machdyn_style(compute, "smd/rho", ComputeSMDRho),
    machdyn_style(compute, "smd/tlsph/defgrad", ComputeSMDTLSPHDefgrad),
    machdyn_style(compute, "smd/tlsph/dt", ComputeSMDTlsphDt),
    machdyn_style(compute, "smd/tlsph/num/neighs", ComputeSMDTLSPHNumNeighs),
    machdyn_style(compute, "smd/tlsph/shape", ComputeSmdTlsphShape),
    machdyn_style(compute, "smd/tlsph/strain", ComputeSMDTLSPHstrain),
    machdyn_style(compute, "smd/tlsph/strain/rate", ComputeSMDTLSPHStrainRate),
    machdyn_style(compute, "smd/tlsph/stress", ComputeSMDTLSPHStress),
    machdyn_style(compute, "smd/triangle/vertices", ComputeSMDTriangleVertices),
    machdyn_style(compute, "smd/ulsph/effm", ComputeSMD_Ulsph_Effm),
    machdyn_style(compute, "smd/ulsph/num/neighs", ComputeSMDULSPHNumNeighs),
    machdyn_style(compute, "smd/ulsph/strain", ComputeSMDULSPHstrain),
    machdyn_style(compute, "smd/ulsph/strain/rate", ComputeSMDULSPHStrainRate),
    machdyn_style(compute, "smd/ulsph/stress", ComputeSMDULSPHStress),
    machdyn_style(compute, "smd/vol", ComputeSMDVol),
};
const int NSTYLES = sizeof(STYLES) / sizeof(STYLES[0]);

const char *AUTHOR = "Georg C. Ganzenmueller (MACHDYN); registration: tools/peers/machdyn_plugin.cpp";

// Enter one style directly into the host's style tables (what src/PLUGIN's plugin_register does, plus atom).
bool enter_style(LAMMPS *lmp, const Style &s)
{
  if (strcmp(s.style, "atom") == 0) {
    (*lmp->atom->avec_map)[s.name] = reinterpret_cast<Atom::AtomVecCreator>(s.v1);
  } else if (strcmp(s.style, "pair") == 0) {
    (*lmp->force->pair_map)[s.name] = reinterpret_cast<Force::PairCreator>(s.v1);
  } else if (strcmp(s.style, "fix") == 0) {
    (*lmp->modify->fix_map)[s.name] = reinterpret_cast<Modify::FixCreator>(s.v2);
  } else if (strcmp(s.style, "compute") == 0) {
    (*lmp->modify->compute_map)[s.name] = reinterpret_cast<Modify::ComputeCreator>(s.v2);
  } else {
    return false;
  }
  return true;
}

}    // namespace

// Standard LAMMPS plugin entry point (`plugin load machdynplugin.so`).
extern "C" void lammpsplugin_init(void *lmpptr, void *handle, void *regfunc)
{
  LAMMPS *lmp = static_cast<LAMMPS *>(lmpptr);
  lammpsplugin_regfunc register_plugin = (lammpsplugin_regfunc) regfunc;
  int natom = 0, nother = 0;
  for (const Style &s : STYLES) {
    if (strcmp(s.style, "atom") == 0) {
      // the host's plugin loader has no atom styles: enter it directly
      enter_style(lmp, s);
      ++natom;
      continue;
    }
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = s.style;
    plugin.name = s.name;
    // the host keeps a copy of the struct (pointers included) in its plugin list: static storage
    static std::string info[NSTYLES];
    const int k = &s - STYLES;
    info[k] = std::string("MACHDYN ") + s.style + " style " + s.name + " (" + s.cls + ")";
    plugin.info = info[k].c_str();
    plugin.author = AUTHOR;
    if (s.v1)
      plugin.creator.v1 = s.v1;
    else
      plugin.creator.v2 = s.v2;
    plugin.handle = handle;
    (*register_plugin)(&plugin, lmp);
    ++nother;
  }
  if (lmp->comm->me == 0)
    utils::logmesg(lmp, "MACHDYN plugin: {} atom style entered directly, {} pair/fix/compute styles "
                   "registered through the plugin loader\n", natom, nother);
}

// Enter every MACHDYN style directly (no `plugin` command needed). Returns the number of styles.
extern "C" int machdyn_register(void *lmpptr)
{
  LAMMPS *lmp = static_cast<LAMMPS *>(lmpptr);
  int n = 0;
  for (const Style &s : STYLES) n += enter_style(lmp, s) ? 1 : 0;
  if (lmp->comm->me == 0)
    utils::logmesg(lmp, "MACHDYN plugin: {} styles entered directly (LAMMPS {})\n", n, LAMMPS_VERSION);
  return n;
}

// Add the `plugin` command (src/PLUGIN/plugin.cpp, compiled into this library) to a LAMMPS instance built
// without the PLUGIN package. Returns 1 if added, 0 if the instance had one already.
extern "C" int machdyn_enable_plugin_command(void *lmpptr)
{
  LAMMPS *lmp = static_cast<LAMMPS *>(lmpptr);
  auto cmap = lmp->input->command_map;
  if (cmap->find("plugin") != cmap->end()) return 0;
  (*cmap)["plugin"] = &command_creator<Plugin>;
  if (lmp->comm->me == 0)
    utils::logmesg(lmp, "MACHDYN plugin: added the `plugin` command (src/PLUGIN, LAMMPS {})\n", LAMMPS_VERSION);
  return 1;
}
