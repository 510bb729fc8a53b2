// The type-dependent measurements for contact::bin_float_100 (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_bin_float_100() {
  static const type_ops ops = typed::make_ops<contact::bin_float_100>();
  return ops;
}
}  // namespace report
