// The type-dependent measurements for contact::bin_float_50 (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_bin_float_50() {
  static const type_ops ops = typed::make_ops<contact::bin_float_50>();
  return ops;
}
}  // namespace report
