// The type-dependent measurements for float (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_float() {
  static const type_ops ops = typed::make_ops<float>();
  return ops;
}
}  // namespace report
