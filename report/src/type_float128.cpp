// The type-dependent measurements for contact::float128 (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_float128() {
  static const type_ops ops = typed::make_ops<contact::float128>();
  return ops;
}
}  // namespace report
