# Findcontact_GMP: the GNU multiple precision library (gmp.h, libgmp), which
# contact::reference (exact rationals) and, through MPFR, contact::types need.
# Debian 12 ships no CMake package for GMP: this module is installed with
# contact's package config, which uses it; the build tree uses it too.
#
# Defines the IMPORTED target contact::gmp and contact_GMP_FOUND,
# contact_GMP_VERSION. Search hints: contact_GMP_ROOT (variable or environment),
# CMAKE_PREFIX_PATH, pkg-config's gmp.pc, or the cache entries
# contact_GMP_INCLUDE_DIR and contact_GMP_LIBRARY set by hand.
include(FindPackageHandleStandardArgs)

find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(_contact_pc_gmp QUIET gmp)
endif()
find_path(contact_GMP_INCLUDE_DIR gmp.h HINTS ${_contact_pc_gmp_INCLUDEDIR} ${_contact_pc_gmp_INCLUDE_DIRS})
find_library(contact_GMP_LIBRARY NAMES gmp libgmp HINTS ${_contact_pc_gmp_LIBDIR} ${_contact_pc_gmp_LIBRARY_DIRS})
mark_as_advanced(contact_GMP_INCLUDE_DIR contact_GMP_LIBRARY)

unset(contact_GMP_VERSION)
if(contact_GMP_INCLUDE_DIR AND EXISTS "${contact_GMP_INCLUDE_DIR}/gmp.h")
  file(STRINGS "${contact_GMP_INCLUDE_DIR}/gmp.h" _contact_gmp_version_lines
       REGEX "^#define[ \t]+__GNU_MP_VERSION(_MINOR|_PATCHLEVEL)?[ \t]+[0-9]+")
  foreach(_contact_part "" _MINOR _PATCHLEVEL)
    string(REGEX MATCH "__GNU_MP_VERSION${_contact_part}[ \t]+([0-9]+)" _contact_match "${_contact_gmp_version_lines}")
    if(_contact_match)
      string(APPEND contact_GMP_VERSION "${CMAKE_MATCH_1}.")
    endif()
  endforeach()
  string(REGEX REPLACE "\\.$" "" contact_GMP_VERSION "${contact_GMP_VERSION}")
endif()

find_package_handle_standard_args(contact_GMP
  REQUIRED_VARS contact_GMP_LIBRARY contact_GMP_INCLUDE_DIR
  VERSION_VAR contact_GMP_VERSION
  REASON_FAILURE_MESSAGE "GMP (gmp.h and libgmp) not found: install it (Debian: libgmp-dev) or point contact_GMP_ROOT or CMAKE_PREFIX_PATH at its prefix")

if(contact_GMP_FOUND AND NOT TARGET contact::gmp)
  add_library(contact::gmp UNKNOWN IMPORTED)
  set_target_properties(contact::gmp PROPERTIES
    IMPORTED_LOCATION "${contact_GMP_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${contact_GMP_INCLUDE_DIR}")
endif()
