#!/bin/bash -eu
# OSS-Fuzz / ClusterFuzzLite entry point: the infrastructure sets CC, CXX,
# CFLAGS, CXXFLAGS, LIB_FUZZING_ENGINE, OUT and WORK; fuzz/build.sh honours them.
exec "$SRC/contact/fuzz/build.sh"
