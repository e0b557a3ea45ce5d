# Synthesis report for the iCE40 UP5K: `cmake --build BUILD --target synth-report` writes
# BUILD/reports/synth.json, one object per design with lut4, dsp, ebr, spram (cells after Debian
# Yosys `synth_ice40 -dsp`) and fmax_mhz (nextpnr-ice40 --up5k). Not part of the default build or
# the tests: place-and-route takes minutes. `--target synth-breakdown-NAME` counts design NAME's
# cells per module instead (BUILD/reports/synth/NAME.modules.txt), `--target
# synth-attribution-NAME` the flattened design's cells by signal scope (NAME.attribution.txt),
# `--target synth-spread-NAME` the LUT4 count over HTX_SYNTH_SPREAD_VARIANTS versions of the same
# logic that differ only in Yosys's internal numbering (NAME.spread.json: ABC's spread, against
# which an RTL change's saving is judged).
#
# HTX_SYNTH_DESIGNS lists the designs. For each design NAME:
#   HTX_SYNTH_<NAME>_AREA_TOP  top whose cells are counted (registered with htx_rtl_top)
#   HTX_SYNTH_<NAME>_PNR_TOP   top placed and routed for Fmax (default: the area top); a harness
#                              with few IOs when the area top has too many pins for the package
#   HTX_SYNTH_<NAME>_FREQ      target MHz given to nextpnr (default 30)
# Later units append their designs to HTX_SYNTH_DESIGNS and set these variables before this file
# is included (the top-level CMakeLists includes it after every RTL directory).

set(HTX_SYNTH_DESIGNS ${HTX_SYNTH_DESIGNS} cpu_up5k soc_up5k)
set(HTX_SYNTH_cpu_up5k_AREA_TOP htx_cpu)
set(HTX_SYNTH_cpu_up5k_PNR_TOP htx_cpu_synth_wrapper)  # hw/rtl/cpu: few IOs, same core paths
set(HTX_SYNTH_soc_up5k_AREA_TOP htx_soc_synth_top)

find_program(HTX_NEXTPNR_ICE40 nextpnr-ice40)
set(HTX_SYNTH_DIR ${CMAKE_BINARY_DIR}/reports/synth)
set(HTX_SYNTH_ATTRIB_DEPTH 7 CACHE STRING "scope parts in the synth-attribution tables")
set(HTX_SYNTH_SPREAD_VARIANTS 10 CACHE STRING "area syntheses of one design in synth-spread")
set(outputs)
foreach(d IN LISTS HTX_SYNTH_DESIGNS)
  set(area_top ${HTX_SYNTH_${d}_AREA_TOP})
  set(pnr_top ${HTX_SYNTH_${d}_PNR_TOP})
  if(NOT pnr_top)
    set(pnr_top ${area_top})
  endif()
  set(freq ${HTX_SYNTH_${d}_FREQ})
  if(NOT freq)
    set(freq 30)
  endif()
  get_property(area_src GLOBAL PROPERTY HTX_RTL_${area_top}_SOURCES)
  get_property(pnr_src GLOBAL PROPERTY HTX_RTL_${pnr_top}_SOURCES)
  if(NOT area_src OR NOT pnr_src)
    message(STATUS "synth-report: skipping ${d} (${area_top} or ${pnr_top} not registered)")
    continue()
  endif()
  list(JOIN area_src "|" area_src_arg)
  list(JOIN pnr_src "|" pnr_src_arg)
  set(out ${HTX_SYNTH_DIR}/${d}.json)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DNAME=${d} -DAREA_TOP=${area_top} -DPNR_TOP=${pnr_top} -DFREQ=${freq}
      "-DAREA_SOURCES=${area_src_arg}" "-DPNR_SOURCES=${pnr_src_arg}" -DWORK=${HTX_SYNTH_DIR}
      -DYOSYS=${HTX_YOSYS_BIN} "-DYOSYS_DEFINES=${HTX_YOSYS_DEFINES}" -DNEXTPNR=${HTX_NEXTPNR_ICE40}
      -DOUT=${out}
      -P ${CMAKE_SOURCE_DIR}/cmake/HtxSynthRun.cmake
    DEPENDS ${area_src} ${pnr_src} ${CMAKE_SOURCE_DIR}/cmake/HtxSynthRun.cmake htx_regs_sv
    COMMENT "synth-report: ${d} (yosys synth_ice40, nextpnr-ice40 --up5k)"
    VERBATIM)
  list(APPEND outputs ${out})
  # The same area top counted per module (docs/area.md): `--target synth-breakdown-NAME`.
  add_custom_target(synth-breakdown-${d}
    COMMAND ${CMAKE_COMMAND} -DNAME=${d} -DTOP=${area_top} "-DSOURCES=${area_src_arg}"
      -DWORK=${HTX_SYNTH_DIR} -DYOSYS=${HTX_YOSYS_BIN} "-DYOSYS_DEFINES=${HTX_YOSYS_DEFINES}"
      -DOUT=${HTX_SYNTH_DIR}/${d}.modules.txt
      -P ${CMAKE_SOURCE_DIR}/cmake/HtxSynthBreakdown.cmake
    DEPENDS htx_regs_sv
    COMMENT "synth-breakdown: ${d} (yosys synth_ice40 -noflatten, by module)"
    VERBATIM)
  # The same area top flattened, by signal scope (docs/area.md): `--target synth-attribution-NAME`;
  # HTX_SYNTH_ATTRIB_DEPTH scope parts deep.
  add_custom_target(synth-attribution-${d}
    COMMAND ${CMAKE_COMMAND} -DNAME=${d} -DTOP=${area_top} "-DSOURCES=${area_src_arg}"
      -DWORK=${HTX_SYNTH_DIR} -DYOSYS=${HTX_YOSYS_BIN} "-DYOSYS_DEFINES=${HTX_YOSYS_DEFINES}"
      -DTOOL=$<TARGET_FILE:htx-synth-attrib> -DDEPTH=${HTX_SYNTH_ATTRIB_DEPTH}
      -DOUT=${HTX_SYNTH_DIR}/${d}.attribution.txt
      -P ${CMAKE_SOURCE_DIR}/cmake/HtxSynthAttribution.cmake
    DEPENDS htx_regs_sv htx-synth-attrib
    COMMENT "synth-attribution: ${d} (yosys synth_ice40, flattened, by signal scope)"
    VERBATIM)
  # The area synthesis over variants of the same logic (cmake/HtxSynthSpread.cmake):
  # `--target synth-spread-NAME`.
  add_custom_target(synth-spread-${d}
    COMMAND ${CMAKE_COMMAND} -DNAME=${d} -DTOP=${area_top} "-DSOURCES=${area_src_arg}"
      -DWORK=${HTX_SYNTH_DIR} -DYOSYS=${HTX_YOSYS_BIN} "-DYOSYS_DEFINES=${HTX_YOSYS_DEFINES}"
      -DVARIANTS=${HTX_SYNTH_SPREAD_VARIANTS} -DOUT=${HTX_SYNTH_DIR}/${d}.spread.json
      -P ${CMAKE_SOURCE_DIR}/cmake/HtxSynthSpread.cmake
    DEPENDS htx_regs_sv
    COMMENT "synth-spread: ${d} (yosys synth_ice40 over ${HTX_SYNTH_SPREAD_VARIANTS} numberings)"
    VERBATIM)
endforeach()

add_custom_target(synth-report
  COMMAND ${CMAKE_COMMAND} -DOUT=${CMAKE_BINARY_DIR}/reports/synth.json "-DPARTS=${outputs}"
    -P ${CMAKE_SOURCE_DIR}/cmake/HtxSynthMerge.cmake
  DEPENDS ${outputs}
  COMMENT "synth-report: writing reports/synth.json"
  VERBATIM)
