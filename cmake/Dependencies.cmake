# Every third-party library Maquette uses, all from Debian 12 packages (scripts/setup.sh).
find_package(Threads REQUIRED)
# Debian ships GeographicLib's find module, not a config file.
list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)
find_package(PROJ REQUIRED CONFIG)
find_package(GDAL CONFIG REQUIRED)
find_package(TBB REQUIRED)
find_package(spdlog REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(CLI11 REQUIRED)
find_package(SQLite3 REQUIRED)
find_package(zstd REQUIRED)
find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs)
find_package(Eigen3 REQUIRED NO_MODULE)
# meshoptimizer (MIT): simplifying meshes for content layers' coarser levels (formats/gltf).
find_package(meshoptimizer REQUIRED CONFIG)
find_package(GTest REQUIRED)
find_package(benchmark REQUIRED)
# libs2 (only for the side-by-side grid benchmark) has neither a config file nor a .pc file.
find_library(S2_LIBRARY s2 REQUIRED)
find_path(S2_INCLUDE_DIR s2/s2cell_id.h REQUIRED)
add_library(S2::s2 UNKNOWN IMPORTED)
set_target_properties(S2::s2 PROPERTIES IMPORTED_LOCATION ${S2_LIBRARY}
                                        INTERFACE_INCLUDE_DIRECTORIES ${S2_INCLUDE_DIR})
if(TARGET zstd::libzstd_shared)
  set(MAQUETTE_ZSTD zstd::libzstd_shared)
else()
  set(MAQUETTE_ZSTD zstd::libzstd_static)
endif()
# Optional: `maquette run` under mpirun/srun shares a run among ranks (framework/runtime/ranks.h)
# through the plug-in libmaquette_mpi.so (framework/plugins), the only target linking MPI.
# Without MPI the build is single-process only.
find_package(MPI COMPONENTS CXX)
if(MPI_CXX_FOUND)
  set(MAQUETTE_WITH_MPI ON)
endif()
# OpenVDB, for formats/vdb and the plug-in libmaquette_vdb.so only. Debian's find module
# (cmake/OpenVDB/FindOpenVDB.cmake) demands Boost.Iostreams' development files, which
# libopenvdb-dev does not bring and nothing here needs: the headers and the library are enough
# (libopenvdb.so names its own dependencies), as for libs2 above, with the two libraries its
# headers call: oneTBB and Imath (Debian's build takes its half floats from Imath).
find_package(Imath REQUIRED CONFIG)
find_library(OPENVDB_LIBRARY openvdb REQUIRED)
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
add_library(OpenVDB::openvdb UNKNOWN IMPORTED)
set_target_properties(OpenVDB::openvdb PROPERTIES IMPORTED_LOCATION ${OPENVDB_LIBRARY}
                      INTERFACE_INCLUDE_DIRECTORIES ${OPENVDB_INCLUDE_DIR}
                      INTERFACE_LINK_LIBRARIES "TBB::tbb;Imath::Imath")
