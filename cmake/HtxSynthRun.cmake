# One design of the synthesis report (cmake -P; see HtxSynth.cmake). Writes OUT: {"lut4", "dsp",
# "ebr", "spram", "fmax_mhz", "seed", "fmax_by_seed", "placed", "area_top", "pnr_top",
# "target_mhz"}; "fmax_mhz" is the best over the place-and-route seeds SEEDS (default 1;2;3), "seed"
# the one that reached it. A design nextpnr cannot place or route gets "fmax_mhz": null,
# "placed": false and "pnr_error" (its first error line).
# Logs and netlists stay in WORK.
include(${CMAKE_CURRENT_LIST_DIR}/HtxSynthCommon.cmake)
htx_synth_require(HtxSynthRun NAME AREA_TOP PNR_TOP FREQ AREA_SOURCES PNR_SOURCES WORK YOSYS YOSYS_DEFINES NEXTPNR OUT)
file(MAKE_DIRECTORY ${WORK})
string(REPLACE "|" " " area_files "${AREA_SOURCES}")
string(REPLACE "|" " " pnr_files "${PNR_SOURCES}")


set(area_stat ${WORK}/${NAME}.area.stat.json)
htx_synth_ice40_area("synth-report ${NAME} (${AREA_TOP})" ${AREA_TOP} "${area_files}" ${area_stat} ""
  ${WORK}/${NAME}.area.yosys.log)
htx_synth_cell_count(${area_stat} SB_LUT4 lut4)
htx_synth_cell_count(${area_stat} SB_MAC16 dsp)
htx_synth_ice40_ebr_count(${area_stat} ebr)
htx_synth_cell_count(${area_stat} SB_SPRAM256KA spram)

set(netlist ${WORK}/${NAME}.pnr.netlist.json)
htx_synth_ice40_area("synth-report ${NAME} (${PNR_TOP})" ${PNR_TOP} "${pnr_files}"
  ${WORK}/${NAME}.pnr.stat.json ${netlist} ${WORK}/${NAME}.pnr.yosys.log)
# Place and route once per seed (SEEDS, default 1;2;3) and keep the best: nextpnr's placement moves
# Fmax by about +-0.7 MHz from seed to seed on these designs (docs/cpu_area_log.md), and a board build would
# use the seed that meets timing. Every seed's figure is recorded ("fmax_by_seed"); the chosen seed's
# log is copied to NAME.nextpnr.log.
if(NOT DEFINED SEEDS OR "${SEEDS}" STREQUAL "")
  set(SEEDS 1 2 3)
endif()
string(REPLACE "|" ";" SEEDS "${SEEDS}")

# The design's one clock: the lowest achieved frequency over the clocks nextpnr reports, two
# decimals; "null" when no register-to-register path was timed.
function(report_fmax pnr_report out)
  file(READ ${pnr_report} report)
  string(JSON nclk LENGTH "${report}" fmax)
  set(fmax "")
  if(nclk GREATER 0)
    math(EXPR last "${nclk} - 1")
    foreach(i RANGE ${last})
      string(JSON clk MEMBER "${report}" fmax ${i})
      string(JSON achieved GET "${report}" fmax ${clk} achieved)
      if(fmax STREQUAL "" OR achieved LESS fmax)
        set(fmax ${achieved})
      endif()
    endforeach()
    string(REGEX MATCH "^[0-9]+(\\.[0-9]?[0-9]?)?" fmax "${fmax}")
  else()
    set(fmax null)
  endif()
  set(${out} ${fmax} PARENT_SCOPE)
endfunction()

set(fmax "")
set(best_seed "")
set(by_seed "")
foreach(seed IN LISTS SEEDS)
  set(pnr_report ${WORK}/${NAME}.nextpnr.s${seed}.json)
  set(pnr_log ${WORK}/${NAME}.nextpnr.s${seed}.log)
  execute_process(COMMAND ${NEXTPNR} --up5k --package sg48 --json ${netlist} --freq ${FREQ}
      --pcf-allow-unconstrained --timing-allow-fail --seed ${seed} --report ${pnr_report} -q
      -l ${pnr_log}
    RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    # A design that does not fit the UP5K (or fails to route) still has its cell counts: record
    # them with no Fmax and the reason, so the report covers every design. (Another seed does not
    # make a design fit.)
    set(first_error "nextpnr-ice40 exited with ${rc}")
    if(EXISTS ${pnr_log})
      configure_file(${pnr_log} ${WORK}/${NAME}.nextpnr.log COPYONLY)
      file(STRINGS ${pnr_log} errors REGEX "ERROR:")
      if(errors)
        list(GET errors 0 first_error)
      endif()
    endif()
    string(REGEX REPLACE "[\"\\]" "'" first_error "${first_error}")
    string(STRIP "${first_error}" first_error)
    file(WRITE ${OUT} "{\"lut4\": ${lut4}, \"dsp\": ${dsp}, \"ebr\": ${ebr}, \"spram\": ${spram}, \"fmax_mhz\": null, \"placed\": false, \"pnr_error\": \"${first_error}\", \"area_top\": \"${AREA_TOP}\", \"pnr_top\": \"${PNR_TOP}\", \"target_mhz\": ${FREQ}}")
    message(STATUS "synth-report ${NAME}: ${lut4} LUT4, ${dsp} DSP, ${ebr} EBR, ${spram} SPRAM, not placed (${first_error}; see ${pnr_log})")
    return()
  endif()
  report_fmax(${pnr_report} seed_fmax)
  if(by_seed)
    string(APPEND by_seed ", ")
  endif()
  string(APPEND by_seed "\"${seed}\": ${seed_fmax}")
  if(NOT seed_fmax STREQUAL "null" AND (fmax STREQUAL "" OR seed_fmax GREATER fmax))
    set(fmax ${seed_fmax})
    set(best_seed ${seed})
  endif()
endforeach()
if(fmax STREQUAL "")
  set(fmax null)  # no register-to-register path was timed
  list(GET SEEDS 0 best_seed)
endif()
configure_file(${WORK}/${NAME}.nextpnr.s${best_seed}.log ${WORK}/${NAME}.nextpnr.log COPYONLY)

file(WRITE ${OUT} "{\"lut4\": ${lut4}, \"dsp\": ${dsp}, \"ebr\": ${ebr}, \"spram\": ${spram}, \"fmax_mhz\": ${fmax}, \"seed\": ${best_seed}, \"fmax_by_seed\": {${by_seed}}, \"placed\": true, \"area_top\": \"${AREA_TOP}\", \"pnr_top\": \"${PNR_TOP}\", \"target_mhz\": ${FREQ}}")
message(STATUS "synth-report ${NAME}: ${lut4} LUT4, ${dsp} DSP, ${ebr} EBR, ${spram} SPRAM, ${fmax} MHz (best of seeds ${SEEDS}: {${by_seed}})")
