# Every third-party library comes from a Debian package; scripts/setup.sh installs them all.
# A missing one stops the configure step with the package to install.

function(isolab_require package debian_package)
  find_package(${package} ${ARGN} QUIET)
  if(NOT ${package}_FOUND)
    message(FATAL_ERROR
      "isolab needs ${package}, which was not found.\n"
      "Install the Debian package '${debian_package}' (sudo apt-get install ${debian_package}),\n"
      "or run scripts/setup.sh, which installs every dependency.")
  endif()
endfunction()

isolab_require(Eigen3 libeigen3-dev NO_MODULE)
isolab_require(yaml-cpp libyaml-cpp-dev)
isolab_require(HDF5 libhdf5-dev COMPONENTS C)
# isolab_hdf5: HDF5 for isolab_io, linked statically into the executables that set the target
# property ISOLAB_STATIC_HDF5 (the isolab front and its helpers) and shared everywhere else.
# Debian's shared libhdf5_serial pulls in libcurl, TLS, Kerberos and LDAP for its remote-file
# drivers, which isolab never uses: loading them costs about 10 ms of every start-up (two thirds
# of `isolab --version`). The static libhdf5.a of the same package pulls in only what the code
# calls. It is not position-independent, so shared objects (the Python module) keep the shared
# library.
# (isolab_require finds packages inside a function: HDF5's variables stay there, its target not.)
get_target_property(isolab_hdf5_libraries HDF5::HDF5 INTERFACE_LINK_LIBRARIES)
get_target_property(isolab_hdf5_include_dirs HDF5::HDF5 INTERFACE_INCLUDE_DIRECTORIES)
list(GET isolab_hdf5_libraries 0 isolab_hdf5_shared)
string(REGEX REPLACE "\\.so$" ".a" isolab_hdf5_static "${isolab_hdf5_shared}")
if(NOT EXISTS "${isolab_hdf5_static}")
  message(FATAL_ERROR "isolab needs HDF5's static library ${isolab_hdf5_static} "
                      "(Debian package libhdf5-dev)")
endif()
set(isolab_hdf5_static_libraries ${isolab_hdf5_libraries})
list(REMOVE_AT isolab_hdf5_static_libraries 0)
list(PREPEND isolab_hdf5_static_libraries ${isolab_hdf5_static})
add_library(isolab_hdf5 INTERFACE)
target_include_directories(isolab_hdf5 SYSTEM INTERFACE ${isolab_hdf5_include_dirs})
target_link_libraries(isolab_hdf5 INTERFACE
  "$<IF:$<BOOL:$<TARGET_PROPERTY:ISOLAB_STATIC_HDF5>>,${isolab_hdf5_static_libraries},HDF5::HDF5>")
isolab_require(SUNDIALS libsundials-dev)
isolab_require(pagmo libpagmo-dev)

# SuiteSparse KLU ships no CMake package on Debian 12: find its header and libraries directly.
find_path(KLU_INCLUDE_DIR klu.h PATH_SUFFIXES suitesparse)
foreach(lib klu amd colamd btf suitesparseconfig)
  find_library(SUITESPARSE_${lib}_LIBRARY ${lib})
  if(NOT SUITESPARSE_${lib}_LIBRARY)
    set(KLU_INCLUDE_DIR KLU_INCLUDE_DIR-NOTFOUND)
  endif()
  list(APPEND KLU_LIBRARIES ${SUITESPARSE_${lib}_LIBRARY})
endforeach()
if(NOT KLU_INCLUDE_DIR)
  message(FATAL_ERROR
    "isolab needs SuiteSparse KLU, which was not found.\n"
    "Install the Debian package 'libsuitesparse-dev' (sudo apt-get install libsuitesparse-dev),\n"
    "or run scripts/setup.sh, which installs every dependency.")
endif()
add_library(isolab_klu INTERFACE)
target_include_directories(isolab_klu SYSTEM INTERFACE ${KLU_INCLUDE_DIR})
target_link_libraries(isolab_klu INTERFACE ${KLU_LIBRARIES})
isolab_require(fmt libfmt-dev)
isolab_require(CLI11 libcli11-dev CONFIG)
isolab_require(nlohmann_json nlohmann-json3-dev)
# OpenMPI for `mpirun -np K isolab compare` (the command also runs without mpirun, on threads).
isolab_require(MPI "libopenmpi-dev openmpi-bin" COMPONENTS CXX)
if(ISOLAB_BUILD_TESTS)
  isolab_require(GTest libgtest-dev)
endif()
if(ISOLAB_BUILD_BENCHMARKS)
  isolab_require(benchmark libbenchmark-dev)
endif()
if(ISOLAB_BUILD_PYTHON)
  # Debian's Python, whose numpy, pandas and pytest come from Debian packages: another python3
  # earlier on PATH (pyenv, conda) would build a module that Debian's Python cannot import.
  set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the isolab module is built for")
  isolab_require(Python python3-dev 3.11 COMPONENTS Interpreter Development.Module)
  set(PYBIND11_FINDPYTHON ON)  # pybind11 uses that Python (FindPython), not FindPythonInterp
  isolab_require(pybind11 pybind11-dev CONFIG)
endif()
