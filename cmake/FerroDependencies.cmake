# Every dependency comes from a Debian 12 package, found through CMake's own
# find modules or the package's exported config.
find_package(Eigen3 3.4 REQUIRED CONFIG)
find_package(SUNDIALS 6 REQUIRED CONFIG)
find_package(Boost 1.74 REQUIRED)             # header-only parts: Odeint
find_package(yaml-cpp REQUIRED CONFIG)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(CLI11 REQUIRED CONFIG)
find_package(fmt REQUIRED CONFIG)
find_package(nlohmann_json 3 REQUIRED CONFIG)  # JSON output of the command line
find_package(Threads REQUIRED)
find_package(MPI COMPONENTS C QUIET)           # optional: the sweep's MPI executor
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)

# yaml-cpp 0.7 in Debian exports the plain target name.
if(TARGET yaml-cpp AND NOT TARGET yaml-cpp::yaml-cpp)
  add_library(yaml-cpp::yaml-cpp ALIAS yaml-cpp)
endif()

if(NOT TARGET ferro_hdf5)
  add_library(ferro_hdf5 INTERFACE)
  target_include_directories(ferro_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
  target_link_libraries(ferro_hdf5 INTERFACE ${HDF5_C_LIBRARIES} ${HDF5_LIBRARIES})
  target_compile_definitions(ferro_hdf5 INTERFACE ${HDF5_DEFINITIONS})
endif()
