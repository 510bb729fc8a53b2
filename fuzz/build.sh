#!/usr/bin/env bash
# Builds the libFuzzer targets, the OSS-Fuzz / ClusterFuzzLite way.
#
# Honours CC, CXX, CFLAGS, CXXFLAGS, LIB_FUZZING_ENGINE, OUT (and WORK for
# intermediate files). Without them it builds locally with clang (clang++-14 if
# present), -fsanitize=fuzzer,address,undefined, into /tmp/build-fuzz.
#
# Writes to $OUT, for each target T of differential, cancellation, invariants,
# high_precision, rounded:
#   contact_T                  the fuzzer
#   contact_T.dict             its dictionary of interesting values
#   contact_T.options          max_len and dict, for OSS-Fuzz
#   contact_T_seed_corpus.zip  fuzz/corpus/T plus fuzz/regressions/T
#   contact_claimed_bounds.txt (OSS-Fuzz builds) a copy of proofs/claimed_bounds.txt,
#                              read by the fuzzers from their own directory
#                              at start-up; local builds read the original
#
# Other knobs: JOBS (parallel compiles, default 2), CONTACT_FUZZ_TARGETS (a
# subset, space separated). A target is recompiled only when a source or the
# flags changed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/.." && pwd)

pick_compiler() {  # first of the candidates that exists
  for c in "$@"; do command -v "$c" >/dev/null 2>&1 && { echo "$c"; return; }; done
  echo "$1"
}
local_build=0
if [[ -z "${LIB_FUZZING_ENGINE:-}" ]]; then local_build=1; fi
CC=${CC:-$(pick_compiler clang-14 clang)}
CXX=${CXX:-$(pick_compiler clang++-14 clang++)}
if [[ $local_build == 1 ]]; then
  sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all"
  CFLAGS=${CFLAGS:-"-O1 -g -fno-omit-frame-pointer $sanitize -fsanitize=fuzzer-no-link"}
  CXXFLAGS=${CXXFLAGS:-"-O1 -g -fno-omit-frame-pointer $sanitize -fsanitize=fuzzer-no-link"}
  LIB_FUZZING_ENGINE="-fsanitize=fuzzer"
fi
OUT=${OUT:-/tmp/build-fuzz}
WORK=${WORK:-$OUT/work}
JOBS=${JOBS:-2}
targets=${CONTACT_FUZZ_TARGETS:-"differential cancellation invariants high_precision rounded"}
mkdir -p "$OUT" "$WORK/obj"

# --- quadmath.h: contact/types.hpp (the scalar types' names, float128) needs
# it. clang does not search GCC's private include directory, and adding all of
# it breaks clang (GCC's intrinsics headers), so link just the two headers into
# a directory of their own.
defines=()
quadmath_header=""
for candidate in "$(gcc -print-file-name=include/quadmath.h 2>/dev/null || true)" /usr/lib/gcc/*/*/include/quadmath.h; do
  if [[ -f "$candidate" ]]; then quadmath_header=$candidate; break; fi
done
if [[ -z "$quadmath_header" ]]; then
  echo "build.sh: quadmath.h not found (GCC's libquadmath: Debian libgcc-12-dev, or the gcc package)" >&2
  exit 1
fi
# the solver and the shared verification vocabulary (contact/harness/), then fuzz/
includes=(-I"$root/solver/include" -I"$root/harness/include" -I"$here")
mkdir -p "$WORK/quadmath-include"
ln -sf "$quadmath_header" "$WORK/quadmath-include/quadmath.h"
ln -sf "$(dirname "$quadmath_header")/quadmath_weak.h" "$WORK/quadmath-include/quadmath_weak.h"
includes+=(-isystem "$WORK/quadmath-include")
static_quadmath=$(gcc -print-file-name=libquadmath.a 2>/dev/null || true)
if [[ -f "$static_quadmath" ]]; then quadmath_lib=("$static_quadmath"); else quadmath_lib=(-lquadmath); fi

# --- MPFR and GMP, statically when possible (OSS-Fuzz's runner image has neither).
static_or_dynamic() {  # library name
  local a
  a=$("$CXX" -print-file-name="lib$1.a" 2>/dev/null || true)
  if [[ "$a" == /* && -f "$a" ]]; then echo "$a"; else echo "-l$1"; fi
}
libs=("$(static_or_dynamic mpfr)" "$(static_or_dynamic gmp)" "${quadmath_lib[@]}")

# --- the proven bounds. A local build reads proofs/claimed_bounds.txt itself at
# start-up; an OSS-Fuzz build (LIB_FUZZING_ENGINE set) gets a copy next to the
# fuzzers, found there at run time (the source tree is not on the fuzzing bots).
bounds="$root/proofs/claimed_bounds.txt"
[[ -f "$bounds" ]] || echo "build.sh: $bounds is missing: the fuzzers will refuse to start" >&2
if [[ $local_build == 1 ]]; then
  rm -f "$OUT/contact_claimed_bounds.txt"
  defines+=(-DCONTACT_CLAIMED_BOUNDS="\"$bounds\"")
else
  [[ -f "$bounds" ]] && cp "$bounds" "$OUT/contact_claimed_bounds.txt"
  defines+=(-DCONTACT_CLAIMED_BOUNDS='"contact_claimed_bounds.txt"')
fi

declare -A max_len=([differential]=24 [cancellation]=24 [invariants]=27 [high_precision]=48 [rounded]=24)
declare -A dict=([differential]=double [cancellation]=double [invariants]=invariants [high_precision]=high_precision [rounded]=double)

compile_flags=(-std=gnu++20 $CXXFLAGS "${defines[@]}" "${includes[@]}")
stamp="$CXX ${compile_flags[*]} $LIB_FUZZING_ENGINE ${libs[*]}"

build_one() {
  local t=$1 exe="$OUT/contact_$1" obj="$WORK/obj/$1.o"
  local stamp_file="$WORK/obj/$1.stamp"
  if [[ -x "$exe" && -f "$stamp_file" && "$(cat "$stamp_file")" == "$stamp" ]] &&
     [[ -z "$(find "$here"/*.hpp "$here/targets/$t.cpp" "$root/solver/include" "$root/harness/include" \
               -newer "$exe" -print -quit)" ]]; then
    echo "build.sh: contact_$t is up to date"
    return 0
  fi
  echo "build.sh: compiling contact_$t"
  "$CXX" "${compile_flags[@]}" -c "$here/targets/$t.cpp" -o "$obj"
  # link with $CXX and $CXXFLAGS, as OSS-Fuzz does
  "$CXX" $CXXFLAGS "$obj" -o "$exe" $LIB_FUZZING_ENGINE "${libs[@]}"
  echo "$stamp" >"$stamp_file"
}

pids=()
status=0
for t in $targets; do
  build_one "$t" &
  pids+=($!)
  if (( ${#pids[@]} >= JOBS )); then wait "${pids[0]}" || status=1; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || status=1; done
[[ $status == 0 ]] || { echo "build.sh: a target failed to build" >&2; exit 1; }

for t in $targets; do
  cp "$here/dict/${dict[$t]}.dict" "$OUT/contact_$t.dict"
  printf '[libfuzzer]\nmax_len = %s\ndict = contact_%s.dict\n' "${max_len[$t]}" "$t" >"$OUT/contact_$t.options"
  rm -f "$OUT/contact_${t}_seed_corpus.zip"
  seeds=()
  declare -A seen_names=()
  for d in "$here/corpus/$t" "$here/regressions/$t"; do
    [[ -d "$d" ]] || continue
    while IFS= read -r f; do
      n=$(basename "$f")
      [[ -n "${seen_names[$n]:-}" ]] && continue
      seen_names[$n]=1
      seeds+=("$f")
    done < <(find "$d" -maxdepth 1 -type f ! -name '.*' ! -name 'README*' | sort)
  done
  unset seen_names
  if (( ${#seeds[@]} > 0 )); then
    if command -v zip >/dev/null 2>&1; then
      zip -q -j "$OUT/contact_${t}_seed_corpus.zip" "${seeds[@]}"
    else
      echo "build.sh: zip not found: no seed corpus archive for $t" >&2
    fi
  fi
done
echo "build.sh: fuzzers in $OUT"
