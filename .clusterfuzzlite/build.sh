#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz entry point, as fuzz/build.sh: the infrastructure
# sets CC, CXX, CFLAGS, CXXFLAGS, LIB_FUZZING_ENGINE and OUT. Without them it
# builds locally with clang-14 and -fsanitize=fuzzer,address,undefined into
# /tmp/build-candidate-fuzz.
#
# CANDIDATE is the candidate's source (default: the library's stable path,
# examples/candidates/stable.cpp), MAX_ULP its allowed error (default 4).
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [[ -z "${LIB_FUZZING_ENGINE:-}" ]]; then
  sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all"
  CC=${CC:-clang-14}
  CXX=${CXX:-clang++-14}
  CFLAGS=${CFLAGS:-"-O1 -g -fno-omit-frame-pointer $sanitize -fsanitize=fuzzer-no-link"}
  CXXFLAGS=${CXXFLAGS:-"-O1 -g -fno-omit-frame-pointer $sanitize -fsanitize=fuzzer-no-link"}
  LIB_FUZZING_ENGINE="-fsanitize=fuzzer"
fi
OUT=${OUT:-/tmp/build-candidate-fuzz}
CANDIDATE=${CANDIDATE:-$root/examples/candidates/stable.cpp}
MAX_ULP=${MAX_ULP:-4}
mkdir -p "$OUT"
case "$CANDIDATE" in
  *.c) $CC $CFLAGS -c "$CANDIDATE" -o "$OUT/candidate.o" ;;
  *) $CXX $CXXFLAGS -std=gnu++20 -I"$root/solver/include" -c "$CANDIDATE" -o "$OUT/candidate.o" ;;
esac
$CXX $CXXFLAGS -std=gnu++20 -I"$root/solver/include" -DCONTACT_MAX_ULP="$MAX_ULP" \
  "$root/check/fuzz/candidate_fuzzer.cpp" "$OUT/candidate.o" -o "$OUT/candidate_fuzzer" \
  $LIB_FUZZING_ENGINE -lmpfr -lgmp -lm
echo "built $OUT/candidate_fuzzer from $CANDIDATE"
