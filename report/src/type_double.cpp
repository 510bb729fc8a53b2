// The type-dependent measurements for double (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_double() {
  static const type_ops ops = typed::make_ops<double>();
  return ops;
}
}  // namespace report
