# The ULX3S build (cmake -P; hw/platform/ulx3s/CMakeLists.txt's board-ulx3s target). In WORK:
#   firmware.hex          the firmware ELF as the RAM's $readmemh image (htx image)
#   htx_ulx3s.json        Yosys synth_ecp5 netlist; htx_ulx3s.yosys.log; htx_ulx3s.stat.json
#   htx_ulx3s.report.json cell counts against the LFE5U-85F's, and how far the flow went
#   htx_ulx3s.config, htx_ulx3s.bit, htx_ulx3s.nextpnr.log   where nextpnr-ecp5 and ecppack exist
# nextpnr-ecp5 runs without --timing-allow-fail: a design that misses 25 MHz gets no bitstream.
include(${CMAKE_CURRENT_LIST_DIR}/../../../cmake/HtxSynthCommon.cmake)
htx_synth_require(board-ulx3s HTX ELF SOURCES LPF WORK YOSYS)
file(MAKE_DIRECTORY ${WORK})
string(REPLACE "|" " " files "${SOURCES}")
set(hex ${WORK}/firmware.hex)
htx_board_image(board-ulx3s ${ELF} ${hex} 131072)

# The LFE5U-85F's resources (Lattice's ECP5 family data sheet): LUT4s, 18x18 multipliers, 18-kbit
# block RAMs (DP16KD).
set(device_lut4 83640)
set(device_mult18 156)
set(device_ebr 208)

set(netlist ${WORK}/htx_ulx3s.json)
set(stat ${WORK}/htx_ulx3s.stat.json)
set(log ${WORK}/htx_ulx3s.yosys.log)
# No HTX_ICE40: the modules with iCE40 cells take their behavioural code here; HTX_ECP5 selects
# the board's PLL and DDR outputs (htx_ulx3s_clocks, htx_ulx3s_dvi).
set(script "read_verilog -sv -DHTX_ECP5 ${files}; chparam -set RamInitFile \"${hex}\" htx_ulx3s_top; synth_ecp5 -top htx_ulx3s_top -json ${netlist}; tee -q -o ${stat} stat -json")
message(STATUS "board-ulx3s: yosys synth_ecp5 (about 4 minutes; log ${log})")
htx_synth_yosys(board-ulx3s ${log} "${script}")
htx_synth_cell_count(${stat} LUT4 lut4)
htx_synth_cell_count(${stat} TRELLIS_DPR16X4 dpram)  # 16x4 distributed RAMs, in slices of their own
htx_synth_cell_count(${stat} MULT18X18D mult18)
htx_synth_cell_count(${stat} DP16KD ebr)
htx_synth_cell_count(${stat} TRELLIS_FF ff)
htx_synth_cell_count(${stat} CCU2C carry)

set(placed false)
set(bitstream "")
set(stopped "")
if(NEXTPNR AND ECPPACK)
  set(config ${WORK}/htx_ulx3s.config)
  set(bit ${WORK}/htx_ulx3s.bit)
  message(STATUS "board-ulx3s: nextpnr-ecp5 --85k --package CABGA381 --freq 25")
  execute_process(COMMAND ${NEXTPNR} --85k --package CABGA381 --json ${netlist} --lpf ${LPF}
      --freq 25 --textcfg ${config} -q -l ${WORK}/htx_ulx3s.nextpnr.log
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "board-ulx3s: nextpnr-ecp5 failed (timing or placement); see ${WORK}/htx_ulx3s.nextpnr.log")
  endif()
  set(placed true)
  execute_process(COMMAND ${ECPPACK} --compress ${config} ${bit} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "board-ulx3s: ecppack failed")
  endif()
  set(bitstream ${bit})
else()
  set(stopped "nextpnr-ecp5 or ecppack not installed: synthesis only")
endif()

file(WRITE ${WORK}/htx_ulx3s.report.json "{\"device\": \"LFE5U-85F\", \"firmware\": \"${ELF}\", \"lut4\": ${lut4}, \"lut4_available\": ${device_lut4}, \"distributed_ram_16x4\": ${dpram}, \"mult18\": ${mult18}, \"mult18_available\": ${device_mult18}, \"ebr\": ${ebr}, \"ebr_available\": ${device_ebr}, \"flip_flops\": ${ff}, \"carry_cells\": ${carry}, \"placed\": ${placed}, \"bitstream\": \"${bitstream}\", \"note\": \"${stopped}\"}\n")
message(STATUS "board-ulx3s: ${lut4} LUT4 (+ ${dpram} 16x4 RAMs) of ${device_lut4}, ${mult18} MULT18X18D of ${device_mult18}, ${ebr} DP16KD of ${device_ebr}, ${ff} flip-flops")
if(bitstream)
  message(STATUS "board-ulx3s: bitstream ${bitstream} (load it: htx flash ${bitstream})")
else()
  message(STATUS "board-ulx3s: ${stopped}; netlist ${netlist}, report ${WORK}/htx_ulx3s.report.json")
endif()
