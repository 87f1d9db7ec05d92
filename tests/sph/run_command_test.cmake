# `chipflex run` end to end on a small hydrostatic case: frames, probes, checkpoint,
# restart continuing to a later time; and a bad case key giving one error line, exit 2.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/small.prm "
set dimension = 2
subsection fluid
  set particle spacing = 0.02
  set sound coefficient = 10
end
subsection time
  set end time = 0.05
end
subsection output
  set frame interval = 0.02
  set probe interval = 0.01
end
subsection geometry
  set fluid blocks = 0, 0, 0.3, 0.2
  subsection tank
    set min corner = 0, 0
    set max corner = 0.3, 0.3
  end
end
subsection probes
  set pressure = bottom: 0.15, 0.05
  set water height = middle: 0.15, 0
end
")
execute_process(COMMAND ${CHIPFLEX} run ${WORK}/small.prm --out ${WORK}/out --threads 2
                        --checkpoint-every 0.02
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "run failed (${rc}): ${out} ${err}")
endif()
foreach(f particles.xdmf particles/frame_000000.h5 probes.csv checkpoint.h5)
  if(NOT EXISTS ${WORK}/out/${f})
    message(FATAL_ERROR "missing ${f}")
  endif()
endforeach()
file(STRINGS ${WORK}/out/probes.csv rows)
list(GET rows 0 header)
if(NOT header STREQUAL "time_s,p_bottom_Pa,h_middle_m,lost_particles,peak_fluid_speed_m_s")
  message(FATAL_ERROR "probes.csv header: ${header}")
endif()
execute_process(COMMAND ${CHIPFLEX} run ${WORK}/small.prm --out ${WORK}/out --threads 2
                        --restart ${WORK}/out/checkpoint.h5 --end-time 0.08
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "restarted from")
  message(FATAL_ERROR "restart failed (${rc}): ${out} ${err}")
endif()

file(WRITE ${WORK}/bad.prm "subsection fluid\n  set particle spacingg = 0.01\nend\n")
execute_process(COMMAND ${CHIPFLEX} run ${WORK}/bad.prm --out ${WORK}/bad
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(STRIP "${err}" err)
string(FIND "${err}" "\n" newline)
if(NOT rc EQUAL 2 OR NOT err MATCHES "particle spacingg" OR NOT newline EQUAL -1)
  message(FATAL_ERROR "bad key: expected one error line naming the key, exit 2; got ${rc}: ${err}")
endif()
file(WRITE ${WORK}/bad2.prm "subsection fluid\n  set gravity = 0, minus ten\nend\n")
execute_process(COMMAND ${CHIPFLEX} run ${WORK}/bad2.prm --out ${WORK}/bad
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "gravity.*minus ten")
  message(FATAL_ERROR "bad value: expected an error naming key and value; got ${rc}: ${err}")
endif()
execute_process(COMMAND ${CHIPFLEX} run ${WORK}/missing.prm --out ${WORK}/bad
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "missing.prm")
  message(FATAL_ERROR "missing file: got ${rc}: ${err}")
endif()
