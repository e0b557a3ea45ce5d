# Area of one synthesis-report design, flattened as the report synthesises it, by the scope of
# the signals its cells compute (cmake -P; see HtxSynth.cmake): Yosys `synth_ice40 -dsp` writes the
# JSON netlist and htx-synth-attrib (host_tools/synth_attrib) sums SB_LUT4, SB_CARRY and
# flip-flops by scope, DEPTH parts deep. Writes OUT (a text table) and prints it.
foreach(v NAME TOP SOURCES WORK YOSYS YOSYS_DEFINES TOOL DEPTH OUT)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "HtxSynthAttribution: ${v} is not set (is yosys installed?)")
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORK})
string(REPLACE "|" " " files "${SOURCES}")
set(netlist ${WORK}/${NAME}.flat.json)
set(log ${WORK}/${NAME}.flat.yosys.log)
execute_process(COMMAND ${YOSYS} -q -l ${log} -p
  "read_verilog -sv ${YOSYS_DEFINES} ${files}; synth_ice40 -dsp -top ${TOP} -json ${netlist}"
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "synth-attribution ${NAME}: yosys failed; see ${log}")
endif()
execute_process(COMMAND ${TOOL} --netlist ${netlist} --top ${TOP} --depth ${DEPTH} --out ${OUT}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "synth-attribution ${NAME}: htx-synth-attrib failed")
endif()
