#include "io/hdf5_snapshot.hpp"

#include <hdf5.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "io/atomic_output.hpp"

namespace sph {
namespace {

// HDF5 prints its error stack to stderr by default; our own message names the file and the failure in one
// line, so the stack is switched off (once, for the process) before any HDF5 call of ours. And HDF5 closes what
// is open at exit: after a failed write (a full disk) its close of that file crashes (SIGSEGV, 1.10.8) where the
// run should exit with its error; every series is closed by its own code, so that clean-up is not registered.
void quiet_hdf5() {
  static const bool once = (H5dont_atexit(), H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr), true);
  (void)once;
}

void check(herr_t status, const char* what) {
  if (status < 0) throw std::runtime_error(std::string("HDF5: ") + what + " failed");
}
hid_t checked(hid_t id, const char* what) {
  if (id < 0) throw std::runtime_error(std::string("HDF5: ") + what + " failed");
  return id;
}

void write_dataset(hid_t group, const char* name, const double* data, hsize_t rows, hsize_t cols) {
  hsize_t dims[2] = {rows, cols};
  hid_t space = checked(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), "create dataspace");
  hid_t set = checked(H5Dcreate2(group, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                      "create dataset");
  if (rows > 0) check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset");
  H5Dclose(set);
  H5Sclose(space);
}

std::vector<double> read_dataset(hid_t group, const char* name) {
  hid_t set = checked(H5Dopen2(group, name, H5P_DEFAULT), name);
  hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<double> out(static_cast<std::size_t>(n));
  if (n > 0) check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read dataset");
  H5Sclose(space);
  H5Dclose(set);
  return out;
}

template <class T>
void write_attribute(hid_t obj, const char* name, const T& value) {
  hid_t space = H5Screate(H5S_SCALAR);
  if constexpr (std::is_same_v<T, std::string>) {
    hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, value.size() + 1);
    hid_t attr = checked(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), "create attribute");
    check(H5Awrite(attr, type, value.c_str()), "write attribute");
    H5Aclose(attr);
    H5Tclose(type);
  } else {
    hid_t attr = checked(H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), "create attribute");
    const double v = static_cast<double>(value);
    check(H5Awrite(attr, H5T_NATIVE_DOUBLE, &v), "write attribute");
    H5Aclose(attr);
  }
  H5Sclose(space);
}

double read_double_attribute(hid_t obj, const char* name) {
  hid_t attr = checked(H5Aopen(obj, name, H5P_DEFAULT), name);
  double v = 0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &v), "read attribute");
  H5Aclose(attr);
  return v;
}

std::vector<double> flatten(const std::vector<Vec2>& v) {
  std::vector<double> out(2 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) { out[2 * i] = v[i].x(); out[2 * i + 1] = v[i].y(); }
  return out;
}

std::string group_name(std::size_t i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "snapshot_%06zu", i);
  return buf;
}

}  // namespace

SnapshotSeries::SnapshotSeries(const std::filesystem::path& h5_path, const RunInfo& info)
    : h5_(h5_path), xdmf_(std::filesystem::path(h5_path).replace_extension(".xdmf")),
      uncaught_(std::uncaught_exceptions()) {
  quiet_hdf5();
  if (h5_.has_parent_path()) std::filesystem::create_directories(h5_.parent_path());
  file_ = checked(H5Fcreate(partial_path(h5_).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "create file");
  hid_t root = static_cast<hid_t>(file_);
  write_attribute(root, "driver", info.driver);
  write_attribute(root, "target", info.target);
  write_attribute(root, "code_version", std::string(code_version()));
  write_attribute(root, "date", utc_timestamp());
  for (const auto& [k, v] : info.parameters) write_attribute(root, ("param." + k).c_str(), v);
  std::string given;
  for (const auto& k : info.given) given += (given.empty() ? "" : " ") + k;
  write_attribute(root, "given", given);
}

SnapshotSeries::~SnapshotSeries() {
  if (file_ < 0) return;
  close_or_discard(uncaught_, [this] { close(); }, [this] {
    H5Fclose(static_cast<hid_t>(file_));
    file_ = -1;
    std::filesystem::remove(partial_path(h5_));
    std::filesystem::remove(partial_path(xdmf_));
  });
}

void SnapshotSeries::close() {
  if (file_ < 0) throw std::logic_error(h5_.string() + ": closed twice");
  const herr_t status = H5Fclose(static_cast<hid_t>(file_));
  file_ = -1;
  if (status < 0) throw std::runtime_error(write_error("HDF5: close failed:", partial_path(h5_)));
  commit_partial(partial_path(h5_), h5_);
  write_xdmf(partial_path(xdmf_), h5_.filename().string());
  commit_partial(partial_path(xdmf_), xdmf_);
}

void SnapshotSeries::write(const Snapshot& s) {
  const std::size_t n = s.position.size();
  const bool vel = !s.velocity.empty(), rho = !s.density.empty(), stress = !s.sxx.empty();
  if ((vel && s.velocity.size() != n) || (rho && s.density.size() != n) ||
      (stress && (s.sxx.size() != n || s.syy.size() != n || s.sxy.size() != n)))
    throw std::invalid_argument("snapshot fields have inconsistent particle counts");
  const std::string name = group_name(entries_.size());
  hid_t g = checked(H5Gcreate2(static_cast<hid_t>(file_), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    "create group");
  write_attribute(g, "time", s.time);
  write_attribute(g, "step", static_cast<double>(s.step));
  write_dataset(g, "position", flatten(s.position).data(), n, 2);
  if (vel) write_dataset(g, "velocity", flatten(s.velocity).data(), n, 2);
  if (rho) write_dataset(g, "density", s.density.data(), n, 1);
  if (stress) {
    std::vector<double> t(3 * n);
    for (std::size_t i = 0; i < n; ++i) { t[3 * i] = s.sxx[i]; t[3 * i + 1] = s.syy[i]; t[3 * i + 2] = s.sxy[i]; }
    write_dataset(g, "stress", t.data(), n, 3);
  }
  H5Gclose(g);
  if (H5Fflush(static_cast<hid_t>(file_), H5F_SCOPE_GLOBAL) < 0)
    throw std::runtime_error(write_error("HDF5: write failed:", partial_path(h5_)));
  entries_.push_back({name, s.time, n, vel, rho, stress});
  write_xdmf(partial_path(xdmf_), partial_path(h5_).filename().string());
}

void SnapshotSeries::write_xdmf(const std::filesystem::path& to, const std::string& h5) const {
  errno = 0;
  std::ofstream x(to);
  x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
       "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const Entry& e : entries_) {
    auto item = [&](const char* ds, int cols) {
      x << "     <DataItem Dimensions=\"" << e.n << (cols > 1 ? " " + std::to_string(cols) : "")
        << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ":/" << e.group << "/" << ds
        << "</DataItem>\n";
    };
    x << "   <Grid Name=\"" << e.group << "\" GridType=\"Uniform\">\n    <Time Value=\"" << format_number(e.time)
      << "\"/>\n    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.n << "\"/>\n"
      << "    <Geometry GeometryType=\"XY\">\n";
    item("position", 2);
    x << "    </Geometry>\n";
    if (e.vel) { x << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n"; item("velocity", 2); x << "    </Attribute>\n"; }
    if (e.rho) { x << "    <Attribute Name=\"density\" AttributeType=\"Scalar\" Center=\"Node\">\n"; item("density", 1); x << "    </Attribute>\n"; }
    if (e.stress) { x << "    <Attribute Name=\"stress_xx_yy_xy\" AttributeType=\"Vector\" Center=\"Node\">\n"; item("stress", 3); x << "    </Attribute>\n"; }
    x << "   </Grid>\n";
  }
  x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  x.close();
  if (x.fail()) throw std::runtime_error(write_error("write failed:", to));
}

std::size_t count_snapshots(const std::filesystem::path& h5_path) {
  quiet_hdf5();
  hid_t f = checked(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open file");
  hsize_t n = 0;
  H5G_info_t info;
  check(H5Gget_info(f, &info), "group info");
  n = info.nlinks;
  H5Fclose(f);
  return static_cast<std::size_t>(n);
}

Snapshot read_snapshot(const std::filesystem::path& h5_path, std::size_t index) {
  quiet_hdf5();
  hid_t f = checked(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open file");
  const std::string name = group_name(index);
  if (H5Lexists(f, name.c_str(), H5P_DEFAULT) <= 0) {  // a clear message instead of HDF5's error stack
    H5Fclose(f);
    throw std::runtime_error(h5_path.string() + " has no snapshot " + std::to_string(index));
  }
  hid_t g = checked(H5Gopen2(f, name.c_str(), H5P_DEFAULT), "open snapshot group");
  Snapshot s;
  s.time = read_double_attribute(g, "time");
  s.step = static_cast<long>(read_double_attribute(g, "step"));
  auto unflatten = [](const std::vector<double>& d) {
    std::vector<Vec2> v(d.size() / 2);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec2(d[2 * i], d[2 * i + 1]);
    return v;
  };
  s.position = unflatten(read_dataset(g, "position"));
  if (H5Lexists(g, "velocity", H5P_DEFAULT) > 0) s.velocity = unflatten(read_dataset(g, "velocity"));
  if (H5Lexists(g, "density", H5P_DEFAULT) > 0) s.density = read_dataset(g, "density");
  if (H5Lexists(g, "stress", H5P_DEFAULT) > 0) {
    const auto t = read_dataset(g, "stress");
    for (std::size_t i = 0; i + 2 < t.size(); i += 3) { s.sxx.push_back(t[i]); s.syy.push_back(t[i + 1]); s.sxy.push_back(t[i + 2]); }
  }
  H5Gclose(g);
  H5Fclose(f);
  return s;
}

std::vector<std::pair<std::string, std::string>> snapshot_header(const std::filesystem::path& h5_path) {
  quiet_hdf5();
  hid_t f = checked(H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open file");
  std::vector<std::pair<std::string, std::string>> out;
  auto text = [](hid_t obj, const char* name, const H5A_info_t*, void* data) -> herr_t {
    hid_t attr = H5Aopen(obj, name, H5P_DEFAULT);
    if (attr < 0) return -1;
    hid_t type = H5Aget_type(attr);
    if (H5Tget_class(type) == H5T_STRING) {  // the run's record: every root attribute is a text
      std::string value(H5Tget_size(type), '\0');
      if (H5Aread(attr, type, value.data()) >= 0) {
        value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
        static_cast<std::vector<std::pair<std::string, std::string>>*>(data)->emplace_back(name, value);
      }
    }
    H5Tclose(type);
    H5Aclose(attr);
    return 0;
  };
  const herr_t status = H5Aiterate2(f, H5_INDEX_NAME, H5_ITER_INC, nullptr, text, &out);
  H5Fclose(f);
  if (status < 0) throw std::runtime_error(h5_path.string() + ": cannot read its root attributes");
  return out;
}

}  // namespace sph
