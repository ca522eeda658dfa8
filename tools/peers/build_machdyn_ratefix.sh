#!/usr/bin/env bash
# The MACHDYN plugin with one line added to smd/ulsph's perfectly plastic stress update: a variant for telling how
# much that update moves the slab under tension (tools/peers/scene_slab.py, variant ulsph_art0.3_ratefix).
#
# Why: in this LAMMPS (20220106) PairULSPH::AssembleStressTensor calls LinearPlasticStrength
# (smd_material_models.cpp), whose yield branch returns as the "rate" sigma_dev_rate = sigmaFinal - sigmaInitial, an
# increment, not divided by dt; the caller then adds dt times it (newStressDeviator = old + dt * (rate + Jaumann
# terms)). So while a particle yields, its deviator moves by dt x the return's increment per step: the plastic flow
# is slowed by the factor dt (in the units of the run; 0.016 for the slab at dp = 0.064), the stress stays at or
# inside the surface but its direction follows the strain rate 1/dt times too slowly. (smd/tlsph uses
# sigmaFinal directly: only ulsph is affected.) The line added after the call,
#   stressRateDev = (newStressDeviator - oldStressDeviator) / dt;
# makes the update new = final + dt x Jaumann terms in the yield branch and leaves the elastic branch as it was
# (there final - old = dt x 2 G d_dev, the same rate up to round-off).
#
# Usage: tools/peers/build_machdyn_ratefix.sh   (after tools/peers/build_machdyn.sh, whose objects and flags it reuses)
#   env MACHDYN_OBJ: the objects of build_machdyn.sh (default machdyn-obj beside its plugin, $MACHDYN_OUT or
#                    build/peers/machdynplugin.so)
#   env MACHDYN_RATEFIX_OUT: the plugin to write (default machdynplugin_ratefix.so beside it)
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
STOCK=${MACHDYN_OUT:-$ROOT/build/peers/machdynplugin.so}  # where build_machdyn.sh left the plugin and its objects
OBJ=${MACHDYN_OBJ:-$(dirname "$STOCK")/machdyn-obj}
OUT=${MACHDYN_RATEFIX_OUT:-$(dirname "$STOCK")/machdynplugin_ratefix.so}
say() { printf 'build_machdyn_ratefix: %s\n' "$*"; }
die() { printf 'build_machdyn_ratefix: ERROR: %s\n' "$*" >&2; exit 1; }
[[ -f $OBJ/flags && -f $OBJ/pair_smd_ulsph.o ]] || die "no MACHDYN objects in $OBJ: run tools/peers/build_machdyn.sh first"
read -r CXX FLAGS < "$OBJ/flags"
MD=$(sed -n 's/.*-I\([^ ]*\/src\/MACHDYN\)\( .*\)\{0,1\}$/\1/p' "$OBJ/flags")
[[ -n $MD && -f $MD/pair_smd_ulsph.cpp ]] || die "cannot find src/MACHDYN from $OBJ/flags"
WORK=$(dirname "$OUT")/machdyn-ratefix
mkdir -p "$WORK"
src=$MD/pair_smd_ulsph.cpp
patched=$WORK/pair_smd_ulsph_ratefix.cpp
anchor='newStressDeviator, stressRateDev, plastic_strain_increment);'
[[ $(grep -cF "$anchor" "$src") == 1 ]] || die "$src: the LinearPlasticStrength call is not where this patch expects it"
sed "s|$anchor|& stressRateDev = (newStressDeviator - oldStressDeviator) / dt;  /* build_machdyn_ratefix.sh */|" "$src" > "$patched.new"
[[ $(grep -c 'build_machdyn_ratefix.sh' "$patched.new") == 1 ]] || die "the patch did not apply"
if cmp -s "$patched.new" "$patched"; then rm "$patched.new"; else mv "$patched.new" "$patched"; fi
o=$WORK/pair_smd_ulsph.o
if [[ ! -f $o || $patched -nt $o || $OBJ/flags -nt $o ]]; then
    say "compiling $patched"
    # shellcheck disable=SC2086
    nice -n 10 $CXX $FLAGS -c "$patched" -o "$o.tmp" && mv "$o.tmp" "$o"
fi
objs=()
for f in "$OBJ"/*.o; do [[ $(basename "$f") == pair_smd_ulsph.o ]] || objs+=("$f"); done
LIBDIR=$(pkg-config --variable=libdir liblammps)
if [[ ! -f $OUT || $o -nt $OUT ]]; then
    nice -n 10 "$CXX" -shared -o "$OUT.tmp" "${objs[@]}" "$o" -L"$LIBDIR" -llammps -Wl,--no-undefined
    mv "$OUT.tmp" "$OUT"
fi
grep -qw machdyn_enable_plugin_command <<<"$(nm -D --defined-only "$OUT")" || die "$OUT exports no machdyn_enable_plugin_command"
say "done: $OUT"
