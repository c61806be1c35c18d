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
