# ABC's spread for one design (cmake -P; see HtxSynth.cmake): the report's area synthesis
# (`synth_ice40 -dsp`) run on VARIANTS versions of the same logic, to tell an RTL change's effect on
# LUT4 from the tens of LUT4 that ABC's mapping moves with the netlist's internal numbering.
# Variant 0 is the sources as they are (the report's figure); variant k adds k one-bit flip-flops that
# nothing reads to the top module (each file holds one module named after it), which Yosys removes
# before mapping, so every variant has the same logic and only the numbering of the cells Yosys
# creates differs. Renaming signals does not move the count. Writes OUT: {"lut4_by_variant": [...],
# "min", "max", "mean"}, and prints one line.
include(${CMAKE_CURRENT_LIST_DIR}/HtxSynthCommon.cmake)
htx_synth_require(HtxSynthSpread NAME TOP SOURCES WORK YOSYS YOSYS_DEFINES VARIANTS OUT)
string(REPLACE "|" ";" sources "${SOURCES}")
set(dir ${WORK}/${NAME}.spread)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})

set(top_file "")
foreach(f IN LISTS sources)
  get_filename_component(base ${f} NAME_WE)
  if(base STREQUAL TOP)
    set(top_file ${f})
  endif()
endforeach()
if(NOT top_file)
  message(FATAL_ERROR "synth-spread ${NAME}: no source named ${TOP}.sv")
endif()
file(READ ${top_file} top_text)
string(FIND "${top_text}" "endmodule" at REVERSE)
if(at EQUAL -1)
  message(FATAL_ERROR "synth-spread ${NAME}: no endmodule in ${top_file}")
endif()
string(SUBSTRING "${top_text}" 0 ${at} top_head)
string(SUBSTRING "${top_text}" ${at} -1 top_tail)

set(by_variant)
set(sum 0)
math(EXPR last "${VARIANTS} - 1")
foreach(k RANGE 0 ${last})
  set(files)
  if(k EQUAL 0)
    set(files ${sources})
  else()
    # k flip-flops of their own, k cells (one k-bit register would be one cell and move the
    # numbering as one does). clk_i and rst_ni: every module of this project has them.
    set(extra "")
    foreach(j RANGE 1 ${k})
      string(APPEND extra "  logic htx_spread_unused${j}_q;\n  always_ff @(posedge clk_i) htx_spread_unused${j}_q <= rst_ni;\n")
    endforeach()
    set(variant ${dir}/v${k}/${TOP}.sv)
    file(WRITE ${variant} "${top_head}${extra}${top_tail}")
    foreach(f IN LISTS sources)
      if(f STREQUAL top_file)
        list(APPEND files ${variant})
      else()
        list(APPEND files ${f})
      endif()
    endforeach()
  endif()
  list(JOIN files " " file_args)
  set(stat ${dir}/v${k}.stat.json)
  htx_synth_ice40_area("synth-spread ${NAME} variant ${k}" ${TOP} "${file_args}" ${stat} ""
    ${dir}/v${k}.yosys.log)
  htx_synth_cell_count(${stat} SB_LUT4 n)
  message(STATUS "synth-spread ${NAME}: variant ${k}: ${n} LUT4")
  list(APPEND by_variant ${n})
  math(EXPR sum "${sum} + ${n}")
endforeach()

set(counts ${by_variant})
list(SORT counts COMPARE NATURAL)
list(GET counts 0 min)
list(GET counts -1 max)
# The mean to one decimal, in integer arithmetic.
math(EXPR mean10 "(${sum} * 10 + ${VARIANTS} / 2) / ${VARIANTS}")
math(EXPR mean_int "${mean10} / 10")
math(EXPR mean_frac "${mean10} % 10")
list(JOIN by_variant ", " by_variant_json)
file(WRITE ${OUT} "{\"lut4_by_variant\": [${by_variant_json}], \"min\": ${min}, \"max\": ${max}, \"mean\": ${mean_int}.${mean_frac}}\n")
message(STATUS "synth-spread ${NAME}: LUT4 over ${VARIANTS} variants: min ${min}, mean ${mean_int}.${mean_frac}, max ${max} (by variant, 0 first: ${by_variant_json}) -> ${OUT}")
