# Findcontact_quadmath: GCC's libquadmath and quadmath.h, the __float128
# maths that Boost.Multiprecision's float128 (contact::types) needs. Both are
# part of GCC (Debian: libgcc-12-dev), in GCC's private directories, which the
# compiler itself reports (-print-file-name); GCC and clang both answer.
#
# Defines the IMPORTED target contact::quadmath and contact_quadmath_FOUND.
# Search hints: contact_quadmath_ROOT, or the cache entries
# contact_quadmath_INCLUDE_DIR and contact_quadmath_LIBRARY set by hand.
#
# quadmath.h lies in GCC's private include directory, which GCC searches but
# clang does not (and clang cannot take that whole directory: its other
# headers are GCC's own). When the compiler does not find quadmath.h by itself,
# the target carries a directory in the build tree that holds links to
# quadmath.h and quadmath_weak.h only.
include(FindPackageHandleStandardArgs)
include(CheckIncludeFileCXX)

set(_contact_quadmath_compiler "${CMAKE_CXX_COMPILER}")
if(NOT _contact_quadmath_compiler)
  set(_contact_quadmath_compiler "${CMAKE_C_COMPILER}")
endif()
set(_contact_quadmath_library_hints "")
set(_contact_quadmath_include_hints "")
if(_contact_quadmath_compiler)
  foreach(_contact_file libquadmath.so include/quadmath.h)
    execute_process(COMMAND "${_contact_quadmath_compiler}" -print-file-name=${_contact_file}
                    OUTPUT_VARIABLE _contact_path OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _contact_rc)
    if(_contact_rc EQUAL 0 AND IS_ABSOLUTE "${_contact_path}" AND EXISTS "${_contact_path}")
      get_filename_component(_contact_dir "${_contact_path}" DIRECTORY)
      get_filename_component(_contact_dir "${_contact_dir}" REALPATH)
      if(_contact_file STREQUAL "libquadmath.so")
        list(APPEND _contact_quadmath_library_hints "${_contact_dir}")
        list(APPEND _contact_quadmath_include_hints "${_contact_dir}/include")
      else()
        list(APPEND _contact_quadmath_include_hints "${_contact_dir}")
      endif()
    endif()
  endforeach()
endif()
file(GLOB _contact_quadmath_gcc_dirs LIST_DIRECTORIES true /usr/lib/gcc/*/*)
list(SORT _contact_quadmath_gcc_dirs COMPARE NATURAL ORDER DESCENDING)

find_library(contact_quadmath_LIBRARY NAMES quadmath libquadmath.so.0
             HINTS ${_contact_quadmath_library_hints} ${CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES}
             PATHS ${_contact_quadmath_gcc_dirs})
set(_contact_quadmath_gcc_include_dirs "")
foreach(_contact_dir IN LISTS _contact_quadmath_gcc_dirs)
  list(APPEND _contact_quadmath_gcc_include_dirs "${_contact_dir}/include")
endforeach()
find_path(contact_quadmath_INCLUDE_DIR quadmath.h
          HINTS ${_contact_quadmath_include_hints} ${CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES}
          PATHS ${_contact_quadmath_gcc_include_dirs})
mark_as_advanced(contact_quadmath_INCLUDE_DIR contact_quadmath_LIBRARY)

find_package_handle_standard_args(contact_quadmath
  REQUIRED_VARS contact_quadmath_LIBRARY contact_quadmath_INCLUDE_DIR
  REASON_FAILURE_MESSAGE "GCC's libquadmath and quadmath.h not found (Debian: libgcc-12-dev, or point contact_quadmath_ROOT at a GCC library directory, or set contact_quadmath_LIBRARY and contact_quadmath_INCLUDE_DIR)")

if(contact_quadmath_FOUND AND NOT TARGET contact::quadmath)
  add_library(contact::quadmath UNKNOWN IMPORTED)
  set_target_properties(contact::quadmath PROPERTIES IMPORTED_LOCATION "${contact_quadmath_LIBRARY}")
  # Does the compiler find quadmath.h by itself (GCC, or flags that say where)?
  set(_contact_quadmath_include "")
  if(CMAKE_CXX_COMPILER_LOADED)
    set(_contact_required_quiet "${CMAKE_REQUIRED_QUIET}")
    set(CMAKE_REQUIRED_QUIET ON)
    check_include_file_cxx(quadmath.h contact_quadmath_HEADER_SEARCHED)
    set(CMAKE_REQUIRED_QUIET "${_contact_required_quiet}")
    if(NOT contact_quadmath_HEADER_SEARCHED)
      if(EXISTS "${contact_quadmath_INCLUDE_DIR}/stddef.h")  # a compiler's private directory: its two headers only
        set(_contact_quadmath_include "${CMAKE_BINARY_DIR}/contact-quadmath-include")
        file(MAKE_DIRECTORY "${_contact_quadmath_include}")
        foreach(_contact_header quadmath.h quadmath_weak.h)
          if(EXISTS "${contact_quadmath_INCLUDE_DIR}/${_contact_header}")
            file(CREATE_LINK "${contact_quadmath_INCLUDE_DIR}/${_contact_header}"
                 "${_contact_quadmath_include}/${_contact_header}" SYMBOLIC COPY_ON_ERROR)
          endif()
        endforeach()
      else()
        set(_contact_quadmath_include "${contact_quadmath_INCLUDE_DIR}")
      endif()
    endif()
  endif()
  if(_contact_quadmath_include)
    set_target_properties(contact::quadmath PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_contact_quadmath_include}")
  endif()
endif()
