# Findcontact_MPFR: the MPFR library (mpfr.h, libmpfr) and the GMP it is built
# on, which contact::reference and contact::types (Boost's mpfr_float) need.
# Debian 12 ships no CMake package for MPFR: this module is installed with
# contact's package config, which uses it; the build tree uses it too.
#
# Defines the IMPORTED target contact::mpfr (which links contact::gmp, see
# Findcontact_GMP.cmake) and contact_MPFR_FOUND, contact_MPFR_VERSION. Search
# hints: contact_MPFR_ROOT (variable or environment), CMAKE_PREFIX_PATH,
# pkg-config's mpfr.pc, or the cache entries contact_MPFR_INCLUDE_DIR and
# contact_MPFR_LIBRARY set by hand.
include(FindPackageHandleStandardArgs)

find_package(contact_GMP QUIET)  # Findcontact_GMP.cmake, next to this file

find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(_contact_pc_mpfr QUIET mpfr)
endif()
find_path(contact_MPFR_INCLUDE_DIR mpfr.h HINTS ${_contact_pc_mpfr_INCLUDEDIR} ${_contact_pc_mpfr_INCLUDE_DIRS})
find_library(contact_MPFR_LIBRARY NAMES mpfr libmpfr HINTS ${_contact_pc_mpfr_LIBDIR} ${_contact_pc_mpfr_LIBRARY_DIRS})
mark_as_advanced(contact_MPFR_INCLUDE_DIR contact_MPFR_LIBRARY)

unset(contact_MPFR_VERSION)
if(contact_MPFR_INCLUDE_DIR AND EXISTS "${contact_MPFR_INCLUDE_DIR}/mpfr.h")
  file(STRINGS "${contact_MPFR_INCLUDE_DIR}/mpfr.h" _contact_mpfr_version_line
       REGEX "^#define[ \t]+MPFR_VERSION_STRING[ \t]+\"[^\"]*\"")
  string(REGEX REPLACE ".*\"([^\"]*)\".*" "\\1" contact_MPFR_VERSION "${_contact_mpfr_version_line}")
endif()

# contact_GMP_FOUND among the required variables: MPFR without GMP is not usable.
find_package_handle_standard_args(contact_MPFR
  REQUIRED_VARS contact_MPFR_LIBRARY contact_MPFR_INCLUDE_DIR contact_GMP_FOUND
  VERSION_VAR contact_MPFR_VERSION
  REASON_FAILURE_MESSAGE "MPFR (mpfr.h and libmpfr) and GMP (gmp.h and libgmp) are needed: install them (Debian: libmpfr-dev, libgmp-dev) or point contact_MPFR_ROOT, contact_GMP_ROOT or CMAKE_PREFIX_PATH at their prefix")

if(contact_MPFR_FOUND AND NOT TARGET contact::mpfr)
  add_library(contact::mpfr UNKNOWN IMPORTED)
  set_target_properties(contact::mpfr PROPERTIES
    IMPORTED_LOCATION "${contact_MPFR_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${contact_MPFR_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES contact::gmp)
endif()
