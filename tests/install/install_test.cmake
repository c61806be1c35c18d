# cmake --install into a fresh prefix, then a consumer project built against it with
# find_package(isolab), and the installed executable's --plot finding its scripts beside it.
# With PYTHON (the Python the module was built for) and PYTHON_DIR (where it is installed, relative
# to the prefix), the installed Python module runs a model from outside the build tree.
# Arguments: BUILD_DIR, SOURCE_DIR, WORK_DIR, LAUNCHER (a compiler launcher such as ccache, or
# empty), PYTHON, PYTHON_DIR. --plot needs Debian's python3-matplotlib and python3-h5py
# (scripts/setup.sh).
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${out}")
  endif()
  message(STATUS "${out}")
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(launcher)
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/consumer
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} ${launcher})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run(${WORK_DIR}/consumer/isolab_consumer ${SOURCE_DIR}/models/paper/table7_thm1_hard.yaml)

# The installed executable: its version, and --plot with the scripts from share/isolab/scripts
# (the build tree's copies are not beside it).
run(${prefix}/bin/isolab --version)
# fit, diagnose, cyclic and shaketable run in libexec/isolab/isolab-search, compare, design and
# synth in libexec/isolab/isolab-studies, which the front starts.
run(${prefix}/bin/isolab fit --help)
run(${prefix}/bin/isolab compare --help)
file(MAKE_DIRECTORY ${WORK_DIR}/run)
run(${prefix}/bin/isolab run ${SOURCE_DIR}/tests/cli/data/run_base.yaml
    -o ${WORK_DIR}/run/sdof.h5 --free-vibration 0 --plot)
foreach(figure sdof_hysteresis.png sdof_hysteresis.pdf)
  if(NOT EXISTS ${WORK_DIR}/run/${figure})
    message(FATAL_ERROR "the installed isolab --plot wrote no ${figure}")
  endif()
endforeach()

# Without the module (configured with -DISOLAB_BUILD_PYTHON=OFF) there is none to install; a
# missing pybind11 or Python stops the configuration itself, naming the package.
if(NOT PYTHON)
  message(STATUS "the Python module was not built (ISOLAB_BUILD_PYTHON=OFF): not tested")
endif()
if(PYTHON)
  # Lines, not "; ": run() passes its arguments on as a list, which a semicolon would split.
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c "import isolab, sys
assert isolab.__file__.startswith(sys.argv[1]), isolab.__file__
print('installed module:', isolab.run(sys.argv[2]).peaks['isolator_displacement'])"
      ${prefix} ${SOURCE_DIR}/tests/cli/data/run_base.yaml)
endif()
