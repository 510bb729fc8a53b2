// The type-dependent measurements for long double (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_long_double() {
  static const type_ops ops = typed::make_ops<long double>();
  return ops;
}
}  // namespace report
