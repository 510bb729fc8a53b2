// The measurements of one registered type: report/CMakeLists.txt compiles this
// file once per index of contact::scalar_types, with CONTACT_REPORT_TYPE_INDEX
// set, so that the types compile in parallel.
#include "typed.hpp"

namespace report {

template <>
type_ops ops_at<CONTACT_REPORT_TYPE_INDEX>() {
  return typed::make_ops<typed::registered<CONTACT_REPORT_TYPE_INDEX>>();
}

}  // namespace report
