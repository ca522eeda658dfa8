#!/usr/bin/env bash
# Build LAMMPS's Smooth Mach Dynamics package (MACHDYN, formerly USER-SMD) as a plugin of Debian's own LAMMPS.
#
# Usage: tools/peers/build_machdyn.sh [SRC_CACHE_DIR]
#   SRC_CACHE_DIR (or env MACHDYN_SRC_DIR): where the Debian source package is fetched and unpacked
#                 (default build/peers/lammps-src).
#   env MACHDYN_OUT: the plugin to write (default build/peers/machdynplugin.so).
#   env MACHDYN_JOBS: parallel compiles (default 2); compiles run under nice -n 10.
#
# Idempotent; every step is skipped when its result is already there:
# 1. apt-get install (only the missing ones) of lammps, liblammps-dev (same version: the headers and library
#    the plugin is compiled against), dpkg-dev (dpkg-source), libeigen3-dev (MACHDYN's only dependency), g++, make.
# 2. The Debian *source* package of lammps, of exactly the version of the installed liblammps-dev: the deb-src
#    entries are derived at run time from the system's own apt sources (apt-get indextargets: URI, suite, component;
#    Signed-By from the sources entry it names), written to a private sources list with private apt lists/cache
#    dirs under the cache dir; the system apt configuration is not touched. `apt-get source --download-only`,
#    then `dpkg-source -x`.
# 3. Compiles src/MACHDYN/*.cpp + tools/peers/machdyn_plugin.cpp (the lammpsplugin_init registration) + the
#    source's src/PLUGIN/plugin.cpp (the `plugin` command, -DLMP_PLUGIN: Debian's lmp lacks it) with the
#    compiler and defines Debian's liblammps was built with (mpicxx when it links Open MPI; -DLAMMPS_SMALLBIG
#    etc. from pkg-config liblammps) into one shared object.
#
# Debian's lmp (20220106) is built without LAMMPS's PLUGIN package: it has no `plugin` command. The plugin
# therefore also exports machdyn_enable_plugin_command(void *lmp), which adds that command to a running LAMMPS
# instance, and machdyn_register(void *lmp), which enters all styles directly; tools/peers/*.in call the first
# from Debian's lmp through its PYTHON package (ctypes) and then use `plugin load` (see those files).
set -euo pipefail

t_start=$(date +%s.%N)
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
SRC_CACHE=${1:-${MACHDYN_SRC_DIR:-$ROOT/build/peers/lammps-src}}
OUT=${MACHDYN_OUT:-$ROOT/build/peers/machdynplugin.so}
JOBS=${MACHDYN_JOBS:-2}
REG_CPP=$ROOT/tools/peers/machdyn_plugin.cpp
mkdir -p "$SRC_CACHE" "$(dirname "$OUT")"
SRC_CACHE=$(cd "$SRC_CACHE" && pwd)

say() { printf 'build_machdyn: %s\n' "$*"; }
die() { printf 'build_machdyn: ERROR: %s\n' "$*" >&2; exit 1; }
elapsed() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN{printf "%.1f s", b-a}'; }

# ---------------------------------------------------------------- 1. Debian packages
PKGS=(lammps liblammps-dev dpkg-dev libeigen3-dev g++ make pkg-config)
missing=()
for p in "${PKGS[@]}"; do
    st=$(dpkg-query -W -f '${db:Status-Abbrev}' "$p" 2>/dev/null || true)
    [[ $st == ii* ]] || missing+=("$p")
done
if ((${#missing[@]})); then
    t=$(date +%s.%N)
    say "apt-get install ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=1200 install -y --no-install-recommends "${missing[@]}"
    say "installed ${missing[*]} in $(elapsed "$t")"
else
    say "Debian packages present: ${PKGS[*]}"
fi
LMP_SRC_PKG=$(dpkg-query -W -f '${source:Package}' liblammps-dev)
LMP_SRC_VER=$(dpkg-query -W -f '${source:Version}' liblammps-dev)
LMP_BIN_VER=$(dpkg-query -W -f '${Version}' liblammps-dev)
[[ $(dpkg-query -W -f '${Version}' lammps) == "$LMP_BIN_VER" ]] || die "lammps and liblammps-dev versions differ"
say "liblammps-dev $LMP_BIN_VER, source package $LMP_SRC_PKG $LMP_SRC_VER"

# ---------------------------------------------------------------- 2. source package
upver=${LMP_SRC_VER#*:}; upver=${upver%-*}            # upstream version: dpkg-source's directory name
SRCDIR=$SRC_CACHE/$LMP_SRC_PKG-$upver
STAMP=$SRCDIR/.machdyn_unpacked_$LMP_SRC_VER
if [[ -f $STAMP && -d $SRCDIR/src/MACHDYN ]]; then
    say "source present: $SRCDIR"
else
    t=$(date +%s.%N)
    APTD=$SRC_CACHE/apt
    mkdir -p "$APTD/lists/partial" "$APTD/cache/archives/partial" "$SRC_CACHE/dl"
    list=$APTD/sources.list
    : > "$list.new"
    # One deb-src line per (repository, suite, component) of the system's deb entries.
    while IFS='|' read -r uri rel comp entry; do
        [[ -n $uri && $uri == */dists/* ]] || continue
        base=${uri%%/dists/*}
        file=${entry%:*}; num=${entry##*:}
        signed=""
        if [[ $file == *.sources ]]; then
            signed=$(awk -v want="$num" 'BEGIN{RS="";FS="\n"}
                { real=0; for(i=1;i<=NF;i++) if($i !~ /^[ \t]*#/ && $i ~ /[^ \t]/) real=1
                  if(!real) next; n++
                  if(n==want) for(i=1;i<=NF;i++) if($i ~ /^[Ss]igned-[Bb]y:/){sub(/^[^:]*:[ \t]*/,"",$i); print $i} }' "$file")
        elif [[ -f $file ]]; then
            signed=$(sed -n "${num}p" "$file" | sed -n 's/.*signed-by=\([^] ]*\).*/\1/p')
        fi
        opt=""
        [[ -n $signed && -f $signed ]] && opt="[signed-by=$signed] "
        echo "deb-src ${opt}$base $rel $comp" >> "$list.new"
    done < <(apt-get indextargets --format '$(URI)|$(RELEASE)|$(COMPONENT)|$(SOURCESENTRY)' 'Identifier: Packages' | sort -u)
    sort -u "$list.new" > "$list"; rm -f "$list.new"
    [[ -s $list ]] || die "could not derive any deb-src entry from the system's apt sources"
    say "private deb-src list $list:"; sed 's/^/    /' "$list"
    APT=(apt-get -o "Dir::Etc::SourceList=$list" -o Dir::Etc::SourceParts=/dev/null
         -o "Dir::State::Lists=$APTD/lists" -o "Dir::Cache=$APTD/cache"
         -o Dir::Cache::pkgcache= -o Dir::Cache::srcpkgcache=)
    say "${APT[*]} update"
    "${APT[@]}" update
    say "${APT[*]} source --download-only $LMP_SRC_PKG=$LMP_SRC_VER"
    (cd "$SRC_CACHE/dl" && "${APT[@]}" source --download-only "$LMP_SRC_PKG=$LMP_SRC_VER")
    dsc=$(ls "$SRC_CACHE/dl/${LMP_SRC_PKG}_${LMP_SRC_VER#*:}.dsc")
    rm -rf "$SRCDIR"
    say "dpkg-source -x $dsc $SRCDIR"
    dpkg-source -x "$dsc" "$SRCDIR"
    [[ -d $SRCDIR/src/MACHDYN ]] || die "no src/MACHDYN in $SRCDIR"
    touch "$STAMP"
    say "fetched and unpacked the source in $(elapsed "$t")"
fi
MD=$SRCDIR/src/MACHDYN
say "MACHDYN sources: $(ls "$MD"/*.cpp | wc -l) .cpp, $(ls "$MD"/*.h | wc -l) .h in $MD"

# ---------------------------------------------------------------- 3. compile
# The installed API headers must be the ones of this source (the plugin uses the rest of src/ as headers).
for h in /usr/include/lammps/*.h; do
    cmp -s "$h" "$SRCDIR/src/$(basename "$h")" || die "$h differs from $SRCDIR/src/$(basename "$h")"
done
LIBLMP=$(pkg-config --variable=libdir liblammps)/liblammps.so
# ldd's output is read whole before grep: under pipefail, `ldd | grep -q` fails when grep's early exit kills ldd
# with SIGPIPE, which took the STUBS branch on a host whose liblammps links Open MPI (CI of stop 50: undefined
# MPI_Allreduce(void*, void*, int, int, int, int) at link time).
LDD_OUT=$(ldd "$LIBLMP")
if grep -q 'libmpi\.so' <<<"$LDD_OUT"; then
    CXX=${CXX_MPI:-mpicxx}; mpi_note="liblammps links $(awk '/libmpi\.so/{print $1}' <<<"$LDD_OUT") -> $CXX ($($CXX --showme:version 2>&1 | sed -n 1p))"
else
    CXX=${CXX:-g++}; mpi_note="liblammps has no MPI library -> $CXX with $SRCDIR/src/STUBS"
fi
command -v "$CXX" >/dev/null || die "compiler $CXX not found"
PC_CFLAGS=$(pkg-config --cflags liblammps)
EIGEN_CFLAGS=$(pkg-config --cflags eigen3)
# Compile-time flags Debian's lmp reports ("Active compile time flags"); only LAMMPS_SMALLBIG changes headers.
CXXFLAGS=(-std=c++11 -O2 -g0 -fPIC -DNDEBUG $PC_CFLAGS -DLAMMPS_GZIP -DLAMMPS_PNG -DLAMMPS_JPEG -DLAMMPS_MEMALIGN=64
          -DLMP_PLUGIN -I"$MD" -I"$SRCDIR/src/PLUGIN" -I"$SRCDIR/src" $EIGEN_CFLAGS -Wno-deprecated-declarations -Wno-ignored-attributes)
[[ $CXX == g++ ]] && CXXFLAGS+=(-I"$SRCDIR/src/STUBS")
say "$mpi_note"
say "flags: ${CXXFLAGS[*]}"

# Every style the package defines must be registered by machdyn_plugin.cpp.
defined=$(grep -hoE '^(AtomStyle|PairStyle|FixStyle|ComputeStyle|CommandStyle|BondStyle)\([^,]+,' "$MD"/*.h \
          | sed -E 's/\(/ /; s/,$//' | sort)
registered=$(grep -oE 'machdyn_style\((atom|pair|fix|compute|command|bond), *"[^"]+"' "$REG_CPP" \
          | sed -E 's/machdyn_style\(([a-z]+), *"([^"]+)"/\1 \2/' \
          | sed -E 's/^atom/AtomStyle/; s/^pair/PairStyle/; s/^fix/FixStyle/; s/^compute/ComputeStyle/; s/^command/CommandStyle/; s/^bond/BondStyle/' | sort)
if [[ $defined != "$registered" ]]; then
    diff <(echo "$defined") <(echo "$registered") >&2 || true
    die "styles defined in $MD (<) and registered in $REG_CPP (>) differ"
fi
say "styles: $(echo "$defined" | wc -l) (all registered): $(echo "$defined" | awk '{printf "%s%s", s, $2; s=" "}')"

OBJ=$(dirname "$OUT")/machdyn-obj
mkdir -p "$OBJ"
echo "$CXX ${CXXFLAGS[*]}" > "$OBJ/flags.new"
cmp -s "$OBJ/flags.new" "$OBJ/flags" || rm -f "$OBJ"/*.o
mv "$OBJ/flags.new" "$OBJ/flags"
srcs=("$MD"/*.cpp "$SRCDIR/src/PLUGIN/plugin.cpp" "$REG_CPP")
todo=()
for s in "${srcs[@]}"; do
    o=$OBJ/$(basename "${s%.cpp}").o
    [[ -f $o && $o -nt $s ]] || todo+=("$s")
done
t=$(date +%s.%N)
if ((${#todo[@]})); then
    say "compiling ${#todo[@]} of ${#srcs[@]} sources with $CXX, $JOBS jobs, nice -n 10"
    export CXX OBJ; export CXXFLAGS_STR="${CXXFLAGS[*]}"
    printf '%s\n' "${todo[@]}" | xargs -P "$JOBS" -I{} sh -c \
        'o="$OBJ/$(basename "{}" .cpp).o"; echo "  $(basename {})"; nice -n 10 $CXX $CXXFLAGS_STR -c "{}" -o "$o.tmp" && mv "$o.tmp" "$o"' \
        || die "compilation failed"
    relink=1
else
    say "objects up to date"
    relink=0
fi
if ((relink)) || [[ ! -f $OUT ]]; then
    nice -n 10 "$CXX" -shared -o "$OUT.tmp" "$OBJ"/*.o -L"$(dirname "$LIBLMP")" -llammps -Wl,--no-undefined
    mv "$OUT.tmp" "$OUT"
    say "linked $OUT ($(du -k "$OUT" | cut -f1) kB); compile+link $(elapsed "$t")"
else
    say "plugin up to date: $OUT"
fi
EXPORTS=$(nm -D --defined-only "$OUT")
for f in lammpsplugin_init machdyn_register machdyn_enable_plugin_command; do
    grep -qw "$f" <<<"$EXPORTS" || die "$OUT exports no $f"
done
say "done in $(elapsed "$t_start"): $OUT"
