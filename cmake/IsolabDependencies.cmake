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

isolab_require(yaml-cpp libyaml-cpp-dev)
isolab_require(fmt libfmt-dev)
isolab_require(CLI11 libcli11-dev CONFIG)
isolab_require(nlohmann_json nlohmann-json3-dev)
if(ISOLAB_BUILD_TESTS)
  isolab_require(GTest libgtest-dev)
endif()
if(ISOLAB_BUILD_BENCHMARKS)
  isolab_require(benchmark libbenchmark-dev)
endif()
