# Helpers of the synthesis scripts that run with cmake -P (HtxSynthRun, HtxSynthBreakdown,
# HtxSynthAttribution, and the boards' builds in hw/platform/*/board_build.cmake).

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

# The synthesis report's own flow (`synth_ice40 -dsp`) on TOP from FILES (space-separated), its
# `stat -json` into STAT_JSON and, unless NETLIST is empty, its netlist; YOSYS_DEFINES are the
# HTX_YOSYS_DEFINES of HtxRtl.cmake (the iCE40 cell instances of a few modules). WHAT names the job
# in the error.
function(htx_synth_ice40_area what top files stat_json netlist log)
  set(script "read_verilog -sv ${YOSYS_DEFINES} ${files}; synth_ice40 -dsp -top ${top}")
  if(netlist)
    string(APPEND script " -json ${netlist}")
  endif()
  string(APPEND script "; tee -q -o ${stat_json} stat -json")
  htx_synth_yosys("${what}" ${log} "${script}")
endfunction()

# The number of cells of type CELL in a Yosys `stat -json` file (0 when there are none) into OUT.
function(htx_synth_cell_count stat_json cell out)
  file(READ ${stat_json} text)
  string(JSON n ERROR_VARIABLE err GET "${text}" design num_cells_by_type ${cell})
  if(err)
    set(n 0)
  endif()
  set(${out} ${n} PARENT_SCOPE)
endfunction()

# A board's RAM initialisation: `htx image` (the program HTX) writes ELF as the $readmemh file HEX
# for a RAM of RAM_BYTES; WHAT names the job in the error.
function(htx_board_image what elf hex ram_bytes)
  if(NOT EXISTS ${elf})
    message(FATAL_ERROR "${what}: ${elf} does not exist (build the firmware first)")
  endif()
  execute_process(COMMAND ${HTX} image ${elf} -o ${hex} --ram-bytes ${ram_bytes} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what}: htx image failed for ${elf}")
  endif()
endfunction()

# The iCE40 block RAMs in a `stat -json` file into OUT, in every clock-polarity form (Yosys maps a
# memory written or read on a falling edge to SB_RAM40_4KNW, NR or NRNW; the CPU's register file
# is written on the falling edge).
function(htx_synth_ice40_ebr_count stat_json out)
  set(ebr 0)
  foreach(kind SB_RAM40_4K SB_RAM40_4KNR SB_RAM40_4KNW SB_RAM40_4KNRNW)
    htx_synth_cell_count(${stat_json} ${kind} n)
    math(EXPR ebr "${ebr} + ${n}")
  endforeach()
  set(${out} ${ebr} PARENT_SCOPE)
endfunction()
