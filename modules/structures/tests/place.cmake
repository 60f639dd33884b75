# structures.place's fit (README-place.md) and its test, on their own: the fit needs only the
# framework's headers. Included from modules/structures/CMakeLists.txt until the module's
# maquette_add_module lists place_stroke.cpp in SOURCES and tests/place_stroke_test.cpp with
# place_stroke.cpp in TESTS, which replaces this file.
add_executable(maquette_structures_place_test ${CMAKE_CURRENT_LIST_DIR}/place_stroke_test.cpp
                                              ${CMAKE_CURRENT_LIST_DIR}/../place_stroke.cpp)
target_include_directories(maquette_structures_place_test PRIVATE ${PROJECT_SOURCE_DIR}/framework)
target_link_libraries(maquette_structures_place_test PRIVATE Eigen3::Eigen ${GeographicLib_LIBRARIES}
                                                             GTest::gtest_main)
maquette_target(maquette_structures_place_test)
gtest_discover_tests(maquette_structures_place_test DISCOVERY_TIMEOUT 60)
