# Area of one synthesis-report design, flattened as the report synthesises it, by the scope of
# the signals its cells compute (cmake -P; see HtxSynth.cmake): Yosys `synth_ice40 -dsp` writes the
# JSON netlist and htx-synth-attrib (host_tools/synth_attrib) sums SB_LUT4, SB_CARRY and
# flip-flops by scope, DEPTH parts deep. Writes OUT (a text table) and prints it.
include(${CMAKE_CURRENT_LIST_DIR}/HtxSynthCommon.cmake)
htx_synth_require(HtxSynthAttribution NAME TOP SOURCES WORK YOSYS YOSYS_DEFINES TOOL DEPTH OUT)
file(MAKE_DIRECTORY ${WORK})
string(REPLACE "|" " " files "${SOURCES}")
set(netlist ${WORK}/${NAME}.flat.json)
htx_synth_yosys("synth-attribution ${NAME}" ${WORK}/${NAME}.flat.yosys.log
  "read_verilog -sv ${YOSYS_DEFINES} ${files}; synth_ice40 -dsp -top ${TOP} -json ${netlist}")
execute_process(COMMAND ${TOOL} --netlist ${netlist} --top ${TOP} --depth ${DEPTH} --out ${OUT}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "synth-attribution ${NAME}: htx-synth-attrib failed")
endif()
