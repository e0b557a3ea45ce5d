# Merges the per-design results of the synthesis report into one JSON object keyed by design name.
set(json "{}")
foreach(part IN LISTS PARTS)
  get_filename_component(name ${part} NAME_WE)
  file(READ ${part} obj)
  string(JSON json SET "${json}" ${name} "${obj}")
endforeach()
file(WRITE ${OUT} "${json}\n")
message(STATUS "synth-report: ${OUT}")
