# ctest driver (package.find_package_consumer): install the build tree into a
# scratch prefix, then configure, build and run consumers of it.
#   -DBUILD=<build tree> -DSOURCE=<this directory> -DSCRATCH=<scratch directory>
#   [-DCXX=<C++ compiler of the build tree>, for the consumers too]
#
# 1. find_package(contact REQUIRED COMPONENTS solver reference types batch):
#    one program per target, all run; fails if any fails.
# 2. find_package(contact REQUIRED), no components, with MPFR, GMP, quadmath
#    and Eigen hidden: contact::solver alone still works with Boost only.
# 3. COMPONENTS batch with Eigen hidden: the configure must fail, naming Eigen3.
set(programs solver reference types batch)
file(REMOVE_RECURSE ${SCRATCH})
set(prefix ${SCRATCH}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix} COMMAND_ERROR_IS_FATAL ANY OUTPUT_QUIET)
set(common -S ${SOURCE} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
if(CXX)
  list(APPEND common -DCMAKE_CXX_COMPILER=${CXX})
endif()
set(hidden -DCMAKE_DISABLE_FIND_PACKAGE_contact_MPFR=ON -DCMAKE_DISABLE_FIND_PACKAGE_contact_GMP=ON
           -DCMAKE_DISABLE_FIND_PACKAGE_contact_quadmath=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON)

# Configures and builds a consumer in ${SCRATCH}/<name>; fatal on failure, with the output.
function(consumer name)
  execute_process(COMMAND ${CMAKE_COMMAND} ${common} -B ${SCRATCH}/${name} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer ${name}: configure failed:\n${out}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${SCRATCH}/${name} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer ${name}: build failed:\n${out}")
  endif()
endfunction()

# 1.
consumer(all)
set(failed "")
foreach(program IN LISTS programs)
  execute_process(COMMAND ${SCRATCH}/all/consumer_${program} RESULT_VARIABLE rc)
  if(rc EQUAL 0)
    message(STATUS "contact::${program}: ok")
  else()
    message(STATUS "contact::${program}: FAILED (${rc})")
    list(APPEND failed contact::${program})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "consumers failed: ${failed}")
endif()

# 2.
consumer(solver-only -DCONSUMER_PROGRAMS=solver "-DCONSUMER_COMPONENTS=" ${hidden})
execute_process(COMMAND ${SCRATCH}/solver-only/consumer_solver RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "contact::solver with Boost only: FAILED (${rc})")
endif()
message(STATUS "contact::solver with Boost only (MPFR, GMP, quadmath, Eigen hidden): ok")

# 3.
execute_process(COMMAND ${CMAKE_COMMAND} ${common} -B ${SCRATCH}/no-eigen -DCONSUMER_PROGRAMS=batch
                        -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0 OR NOT out MATCHES "contact::batch is unavailable, not found: Eigen3")
  message(FATAL_ERROR "COMPONENTS batch without Eigen: expected a failed configure naming Eigen3, got (${rc}):\n${out}")
endif()
message(STATUS "COMPONENTS batch without Eigen: fails as it should")
