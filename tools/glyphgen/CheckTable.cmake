# Runs the generator twice and compares both outputs with each other and with
# the committed table (cmake -P; GENERATOR, NAME, COMMITTED, WORK, FONTS set;
# FONTS separated by |).
string(REPLACE "|" ";" FONTS "${FONTS}")
foreach(run 1 2)
  execute_process(COMMAND ${GENERATOR} ${WORK}/${NAME}.${run}.h ${NAME} ${FONTS}
                  RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "glyphgen failed (${code}) for ${NAME}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${NAME}.1.h ${WORK}/${NAME}.2.h
                RESULT_VARIABLE differ)
if(differ)
  message(FATAL_ERROR "glyphgen is not reproducible: two runs differ for ${NAME}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/${NAME}.1.h ${COMMITTED}
                RESULT_VARIABLE stale)
if(stale)
  message(FATAL_ERROR "${COMMITTED} differs from what glyphgen writes: "
                      "run `cmake --build build --target glyph_tables`")
endif()
