# Warnings for project code: every project target calls maquette_target(NAME).
# GCC 12 reports false -Wrestrict errors inside libstdc++'s std::string at -O2/-O3 (GCC bug
# 105651, fixed in GCC 13), so that one warning stays off with GCC 12.
function(maquette_target name)
  target_compile_options(${name} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${name} PRIVATE -Wno-restrict)
  endif()
endfunction()

# Every GoogleTest executable's tests run with the analysed exemplars (modules/synthesis/
# exemplar_cache.h) cached in the build, as scripts/test.sh sets it, so that a plain `ctest`
# never writes into the user's cache either.
set(MAQUETTE_TEST_ENVIRONMENT "MAQUETTE_CACHE_DIR=${PROJECT_BINARY_DIR}/test-exemplar-cache")

# One line per module (OpenCV style): maquette_add_module(terrain SOURCES ... TESTS ...)
# builds lib/maquette/libmaquette_<name>.so and a GoogleTest executable for its tests.
function(maquette_add_module name)
  cmake_parse_arguments(MOD "" "" "SOURCES;TESTS;LIBS" ${ARGN})
  set(target maquette_${name})
  add_library(${target} MODULE ${MOD_SOURCES})
  target_link_libraries(${target} PRIVATE maquette ${MOD_LIBS})
  set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${MAQUETTE_MODULE_DIR}
                                             CXX_VISIBILITY_PRESET hidden)
  maquette_target(${target})
  install(TARGETS ${target} LIBRARY DESTINATION lib/maquette)
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/..")
  if(MOD_TESTS)
    add_executable(${target}_test ${MOD_TESTS})
    target_link_libraries(${target}_test PRIVATE maquette ${MOD_LIBS} GTest::gtest_main)
    target_compile_definitions(${target}_test PRIVATE
      MAQUETTE_MODULE_DIR="${MAQUETTE_MODULE_DIR}"
      MAQUETTE_BIN_DIR="${PROJECT_BINARY_DIR}/bin"
      MAQUETTE_SHARED_DIR="${PROJECT_SOURCE_DIR}/../shared")
    add_dependencies(${target}_test ${target} maquette_cli)
    maquette_target(${target}_test)
    gtest_discover_tests(${target}_test DISCOVERY_TIMEOUT 60
                         PROPERTIES ENVIRONMENT "${MAQUETTE_TEST_ENVIRONMENT}")
  endif()
endfunction()

# Adds every immediate subfolder of the current folder that has a CMakeLists.txt (tests/ and
# benchmarks/ grow by adding a folder).
function(maquette_add_subfolders)
  file(GLOB dirs LIST_DIRECTORIES true CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*)
  foreach(dir ${dirs})
    if(IS_DIRECTORY ${dir} AND EXISTS ${dir}/CMakeLists.txt)
      add_subdirectory(${dir})
    endif()
  endforeach()
endfunction()

include(${CMAKE_CURRENT_LIST_DIR}/StartupLibraries.cmake)
# Puts the start-up libraries found on this system (StartupLibraries.cmake) first in `target`'s
# DT_NEEDED, even those it calls nothing of, so that the loader loads them first and finds most
# symbols in the first libraries it tries. Call before any other target_link_libraries(target).
function(maquette_startup_order target)
  set(paths)
  foreach(name ${MAQUETTE_STARTUP_LIBRARIES})
    unset(_maquette_startup_library)
    find_library(_maquette_startup_library NAMES ${name} NO_CACHE)
    if(_maquette_startup_library)
      list(APPEND paths ${_maquette_startup_library})
    endif()
  endforeach()
  list(LENGTH paths found)
  list(LENGTH MAQUETTE_STARTUP_LIBRARIES listed)
  if(found LESS listed)
    message(WARNING "${found} of the ${listed} start-up libraries found (cmake/StartupLibraries.cmake "
                    "is for Debian 12's GDAL): regenerate it with scripts/startup-order.sh")
  endif()
  target_link_libraries(${target} PRIVATE "-Wl,--push-state,--no-as-needed" ${paths}
                                          "-Wl,--pop-state")
endfunction()
