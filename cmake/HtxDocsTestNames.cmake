# Every test a document names exists (`cmake -P`, run by the lint test lint.docs.test_names):
# docs/*.md and README.md name tests in backquotes as `Suite.Test`, `Suite.*`, `rtl.fb.Suite.*` or
# `rtl.raster.All/Suite.*`; each must match a test of this build tree's CTest list, so a test
# renamed or removed cannot leave its documentation pointing at nothing.
#   -DSOURCE_DIR=...  -DBUILD_DIR=...  -DCTEST=...  [-DEXTRA_DOC=file: one more document, for the
#   test of this check itself]
execute_process(COMMAND ${CTEST} -N --test-dir ${BUILD_DIR} OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ctest -N failed in ${BUILD_DIR}")
endif()
# One test name a line, each between spaces ("Test #12: name").
string(REGEX MATCHALL "Test +#[0-9]+: [^\n]+" lines "${listing}")
set(names "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "^Test +#[0-9]+: ([^ ]+).*" " \\1 " name "${line}")
  string(APPEND names "${name}")
endforeach()

file(GLOB_RECURSE docs ${SOURCE_DIR}/docs/*.md)
list(APPEND docs ${SOURCE_DIR}/README.md ${EXTRA_DOC})
set(checked 0)
set(missing "")
foreach(doc IN LISTS docs)
  file(READ ${doc} text)
  string(REGEX MATCHALL "`[A-Za-z0-9_./*]+`" tokens "${text}")
  list(REMOVE_DUPLICATES tokens)
  foreach(token IN LISTS tokens)
    string(REGEX REPLACE "`" "" ref "${token}")
    # A test name: an optional lower-case prefix, an optional `Instance/`, then Suite.Name or
    # Suite.*, where both parts are CamelCase with a lower-case letter (register fields such as
    # CTRL.ENABLE are all capitals).
    if(NOT ref MATCHES "^([a-z]+\\.)*([A-Za-z0-9_]+/)?[A-Z][A-Za-z0-9]*[a-z][A-Za-z0-9]*\\.([A-Z][A-Za-z0-9_]*[a-z][A-Za-z0-9_]*\\*?|\\*)$")
      continue()
    endif()
    math(EXPR checked "${checked} + 1")
    string(REPLACE "." "\\." pattern "${ref}")
    string(REPLACE "*" "[^ ]*" pattern "${pattern}")
    if(NOT names MATCHES "[ ./]${pattern}[ /]")
      file(RELATIVE_PATH where ${SOURCE_DIR} ${doc})
      string(APPEND missing "  ${ref} (${where})\n")
    endif()
  endforeach()
endforeach()
if(missing)
  message(FATAL_ERROR "documents name tests this build does not have:\n${missing}")
endif()
message(STATUS "${checked} test names in the documents, each a test of this build")
