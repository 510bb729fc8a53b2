#!/usr/bin/env bash
# extract.sh SOURCE_DIR OUT_DIR: the AVX-512 batch kernel that the Highway
# kernels replaced, as its headers were at the parent of 7712b64, from the
# repository's history: OUT_DIR/as_was as it was, and OUT_DIR/patched with
# today's release formula for u > 0 (compensated_release.patch), so that its
# results are today's bit for bit (but for its far lanes, see README.md).
set -euo pipefail
source_dir=$1 out=$2
commit=4d1d421e6e08a4f80ff37e3b77ff8e301b2de07c
rm -rf "$out"
mkdir -p "$out/as_was" "$out/patched"
if ! git -C "$source_dir" cat-file -e "$commit^{commit}" 2>/dev/null; then
  echo "extract.sh: commit $commit is not in $source_dir's history (a clone with its history is needed)" >&2
  exit 1
fi
# -m: the files dated now, not at the commit, so that the build finds them newer
# than extract.sh and the patch, and does not extract them again at every build
git -C "$source_dir" archive "$commit" solver/include | tar -x -m -C "$out/as_was"
cp -r "$out/as_was/solver" "$out/patched/"
(cd "$out/patched" && git apply -p1 "$source_dir/report/baseline/compensated_release.patch")
