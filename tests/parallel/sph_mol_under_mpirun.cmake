# `sph-mol` itself under mpirun (cmake -P, from tests/CMakeLists.txt): the dam break on 1 rank and
# on 3 ranks writes the same particles (1 rank: the serial .vtp files; 3 ranks: a .pvtp per file
# whose 3 per-rank pieces together hold the same particles and values, compared by PIECES_EQUAL,
# and a .pvd that lists the .pvtp files), the same front positions byte for byte and the same
# checkpoint (state and integrator state); the 3 ranks' checkpoint continued on 2 ranks ends in the
# same state, and so does the 1D Sod tube (energy equation, variable h); ARKODE and CVODE on 2
# ranks end in the particles of 1 rank, and so does the dam break with a reordered workspace; rank 0
# alone prints the summary; a subcommand ends every rank with exit code 2; rank 0 alone reports a
# bad command line. Inputs: SPHMOL,
# PIECES_EQUAL, MPIEXEC, NP_FLAG, FLAGS (comma-separated), SOURCE_DIR, WORK_DIR.
string(REPLACE "," ";" FLAGS "${FLAGS}")
file(REMOVE_RECURSE ${WORK_DIR})
set(sets --set discretization.spacing=0.04 --set time.t_end=0.06 --set output.times=[0.03,0.06]
         --set output.plots=false --set output.vtk=true --set output.checkpoint_every=0.03 --quiet)
set(dam ${SOURCE_DIR}/verification/dam_break.yaml)
foreach(n 1 3)
  execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} ${n} ${FLAGS} ${SPHMOL} --config ${dam} ${sets} --output ${WORK_DIR}/n${n}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${n} ranks: exit ${rc}\n${out}\n${err}")
  endif()
  string(REGEX MATCHALL "case dam_break:" lines "${out}")
  list(LENGTH lines printed)
  if(NOT printed EQUAL 1)
    message(FATAL_ERROR "${n} ranks: the summary was printed ${printed} times\n${out}")
  endif()
endforeach()
# The particles of 1 rank's .vtp in the 3 pieces of 3 ranks' .pvtp.
function(check_pieces serial split pieces what)
  execute_process(COMMAND ${PIECES_EQUAL} ${serial} ${split} ${pieces} RESULT_VARIABLE same ERROR_VARIABLE why)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${what}: ${why}")
  endif()
endfunction()
foreach(f fluid_0000 fluid_0001 fluid_0002 walls_0000 walls_0002)
  check_pieces(${WORK_DIR}/n1/${f}.vtp ${WORK_DIR}/n3/${f}.pvtp 3 "${f}: 3 ranks against 1")
  if(EXISTS ${WORK_DIR}/n3/${f}.vtp)
    message(FATAL_ERROR "3 ranks wrote the serial file ${f}.vtp")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/n1/front.csv ${WORK_DIR}/n3/front.csv RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "front.csv differs between 1 and 3 ranks")
endif()
# The collections: the same entries, with .pvtp files over ranks.
file(READ ${WORK_DIR}/n1/particles.pvd pvd1)
file(READ ${WORK_DIR}/n3/particles.pvd pvd3)
string(REPLACE ".vtp\"" ".pvtp\"" pvd1_as_pieces "${pvd1}")
if(NOT pvd1 MATCHES "file=\"fluid_0002.vtp\"" OR NOT pvd3 STREQUAL pvd1_as_pieces)
  message(FATAL_ERROR "particles.pvd: 3 ranks should list the .pvtp files of the serial entries\n1 rank:\n${pvd1}\n3 ranks:\n${pvd3}")
endif()
foreach(n 1 3)
  file(READ ${WORK_DIR}/n${n}/checkpoint-0.03/checkpoint.json cp${n})
  string(JSON state${n} GET "${cp${n}}" state)
  string(JSON integrator${n} GET "${cp${n}}" integrator_state)
endforeach()
if(NOT state1 STREQUAL state3 OR NOT integrator1 STREQUAL integrator3)
  message(FATAL_ERROR "the checkpoint of 3 ranks holds another state than that of 1 rank")
endif()

# Written by 3 ranks, continued by 2: the end state of the uninterrupted run.
execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} 2 ${FLAGS} ${SPHMOL} --restart ${WORK_DIR}/n3/checkpoint-0.03
                        --output ${WORK_DIR}/restarted --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "restart on 2 ranks: exit ${rc}\n${out}\n${err}")
endif()
check_pieces(${WORK_DIR}/n1/fluid_0002.vtp ${WORK_DIR}/restarted/fluid_0000.pvtp 2
             "3 ranks' checkpoint continued on 2 ranks: the final particles against the uninterrupted run")

# A shipped shock tube (energy equation, h by dh/dt, equal masses): 1 and 3 ranks write the same
# profiles and checkpoint; 3 ranks' checkpoint continued on 2 ends in the profile of 1 rank.
set(sod ${SOURCE_DIR}/verification/sod_1d.yaml)
set(sod_sets --set time.t_end=0.04 --set output.times=[0.02,0.04] --set output.plots=false
             --set output.checkpoint_every=0.02 --quiet)
foreach(n 1 3)
  execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} ${n} ${FLAGS} ${SPHMOL} --config ${sod} ${sod_sets} --output ${WORK_DIR}/sod-n${n}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sod_1d on ${n} ranks: exit ${rc}\n${out}\n${err}")
  endif()
  file(READ ${WORK_DIR}/sod-n${n}/checkpoint-0.02/checkpoint.json sod_cp${n})
  string(JSON sod_state${n} GET "${sod_cp${n}}" state)
endforeach()
foreach(f profile_t0.02.csv profile_t0.04.csv)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/sod-n1/${f} ${WORK_DIR}/sod-n3/${f} RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "sod_1d: ${f} differs between 1 and 3 ranks")
  endif()
endforeach()
if(NOT sod_state1 STREQUAL sod_state3)
  message(FATAL_ERROR "sod_1d: the checkpoint of 3 ranks holds another state than that of 1 rank")
endif()
execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} 2 ${FLAGS} ${SPHMOL} --restart ${WORK_DIR}/sod-n3/checkpoint-0.02
                        --output ${WORK_DIR}/sod-restarted --quiet
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sod_1d restart on 2 ranks: exit ${rc}\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/sod-n1/profile_t0.04.csv
                        ${WORK_DIR}/sod-restarted/profile_t0.04.csv RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "sod_1d: 3 ranks' checkpoint continued on 2 ranks: the final profile differs from the uninterrupted run")
endif()

# ARKODE and CVODE: on 2 ranks the same particles as on 1 (which runs serially), to the bit.
foreach(integrator arkode_erk cvode_adams)
  set(short --set discretization.spacing=0.04 --set time.integrator=${integrator} --set time.t_end=0.02
            --set output.times=[0.02] --set output.plots=false --set output.vtk=true --quiet)
  foreach(n 1 2)
    execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} ${n} ${FLAGS} ${SPHMOL} --config ${dam} ${short}
                            --output ${WORK_DIR}/${integrator}-n${n}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${integrator} on ${n} ranks: exit ${rc}\n${out}\n${err}")
    endif()
  endforeach()
  check_pieces(${WORK_DIR}/${integrator}-n1/fluid_0001.vtp ${WORK_DIR}/${integrator}-n2/fluid_0001.pvtp 2
               "${integrator}: the final particles of 2 ranks against 1")
endforeach()

# Reordering (Morton-sorted workspace): on 2 ranks the same particles as on 1, to the bit.
set(sorted --set discretization.spacing=0.04 --set discretization.reorder=true --set time.t_end=0.06
           --set output.times=[0.06] --set output.plots=false --set output.vtk=true --quiet)
foreach(n 1 2)
  execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} ${n} ${FLAGS} ${SPHMOL} --config ${dam} ${sorted} --output ${WORK_DIR}/reorder-n${n}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "reorder: true on ${n} ranks: exit ${rc}\n${out}\n${err}")
  endif()
endforeach()
check_pieces(${WORK_DIR}/reorder-n1/fluid_0001.vtp ${WORK_DIR}/reorder-n2/fluid_0001.pvtp 2
             "reorder: true: the final particles of 2 ranks against 1")

execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} 2 ${FLAGS} ${SPHMOL} kernels RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "does not run over several MPI ranks")
  message(FATAL_ERROR "a subcommand over 2 ranks: exit ${rc}, expected 2\n${err}")
endif()

# The command line is the same on every rank: its errors and warnings are printed once, by rank 0.
execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} 2 ${FLAGS} ${SPHMOL} --no-such-option RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "was not expected: --no-such-option" lines "${out}${err}")
list(LENGTH lines printed)
if(NOT rc EQUAL 2 OR NOT printed EQUAL 1)
  message(FATAL_ERROR "an unknown option over 2 ranks: exit ${rc} (expected 2), the error printed ${printed} times (expected 1)\n${out}\n${err}")
endif()
execute_process(COMMAND ${MPIEXEC} ${NP_FLAG} 2 ${FLAGS} ${SPHMOL} --threads 100000 kernels RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCHALL "--threads 100000 is more than" lines "${out}${err}")
list(LENGTH lines printed)
if(NOT printed EQUAL 1)
  message(FATAL_ERROR "--threads above the cores over 2 ranks: the warning printed ${printed} times (expected 1)\n${out}\n${err}")
endif()
