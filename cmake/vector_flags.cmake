# CONTACT_VECTOR_FLAGS: the report's instruction-set flags, for the scalar
# paths it times: x86-64-v4 (AVX-512) where the build machine runs it, else
# x86-64-v3 (AVX2 + FMA), else none. (The batch kernels carry their own flags
# and are chosen at run time: solver/CMakeLists.txt.) -ffp-contract=off keeps the compiler from fusing a*b+c
# into an fma where the source has none (GNU mode allows it by default), so
# that batch and scalar paths do the arithmetic as written; -fno-math-errno
# lets sqrt be an instruction. Neither changes a result: IEEE operations stay
# correctly rounded, one by one.
if(CONTACT_REPORT)
  set(CONTACT_VECTOR_ARCH "auto" CACHE STRING "-march for the batch solver's users: auto, none, or a -march value")
  include(CheckCXXSourceRuns)
  function(contact_arch_runs march features result)
    set(CMAKE_REQUIRED_FLAGS "-march=${march}")
    set(test "int main() { __builtin_cpu_init(); return (1")
    foreach(feature ${features})
      string(APPEND test " && __builtin_cpu_supports(\"${feature}\")")
    endforeach()
    string(APPEND test ") ? 0 : 1; }")
    check_cxx_source_runs("${test}" ${result})
    set(${result} ${${result}} PARENT_SCOPE)
  endfunction()
  set(CONTACT_VECTOR_FLAGS -ffp-contract=off -fno-math-errno)
  set(vector_arch "")
  if(CONTACT_VECTOR_ARCH STREQUAL "auto")
    contact_arch_runs(x86-64-v4 "avx512f;avx512dq;avx512bw;avx512vl;fma" CONTACT_HAS_X86_64_V4)
    if(CONTACT_HAS_X86_64_V4)
      set(vector_arch x86-64-v4)
      list(APPEND CONTACT_VECTOR_FLAGS -march=x86-64-v4 -mprefer-vector-width=512)
    else()
      contact_arch_runs(x86-64-v3 "avx2;fma" CONTACT_HAS_X86_64_V3)
      if(CONTACT_HAS_X86_64_V3)
        set(vector_arch x86-64-v3)
        list(APPEND CONTACT_VECTOR_FLAGS -march=x86-64-v3)
      endif()
    endif()
  elseif(NOT CONTACT_VECTOR_ARCH STREQUAL "none")
    set(vector_arch ${CONTACT_VECTOR_ARCH})
    list(APPEND CONTACT_VECTOR_FLAGS -march=${CONTACT_VECTOR_ARCH})
  endif()
  message(STATUS "batch solver: instruction set '${vector_arch}' (CONTACT_VECTOR_ARCH=${CONTACT_VECTOR_ARCH})")
endif()

