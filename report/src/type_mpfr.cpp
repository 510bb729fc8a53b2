// The type-dependent measurements for contact::mpfr_float (see typed.hpp).
#include "typed.hpp"

namespace report {
const type_ops& ops_mpfr() {
  static const type_ops ops = typed::make_ops<contact::mpfr_float>();
  return ops;
}
}  // namespace report
