# Helpers of the synthesis scripts that run with cmake -P (HtxSynthBreakdown, HtxSynthAttribution).

# Every variable named after SCRIPT is set and not empty.
function(htx_synth_require script)
  foreach(v IN LISTS ARGN)
    if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
      message(FATAL_ERROR "${script}: ${v} is not set (is yosys installed?)")
    endif()
  endforeach()
endfunction()

# Yosys (the variable YOSYS) runs the script COMMANDS quietly, its log in LOG; WHAT names the job
# in the error.
function(htx_synth_yosys what log commands)
  execute_process(COMMAND ${YOSYS} -q -l ${log} -p "${commands}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: yosys failed; see ${log}")
  endif()
endfunction()
