# urdfsnap_add_snapshot_test(NAME SUITE [REPORT_DIR DIR] [JUNIT FILE] [LABELS label...]
#                            [LAUNCHER command...])
#
# Adds a CTest test NAME that runs `urdfsnap snapshot check SUITE --report DIR --junit FILE`:
# every case of the suite rendered and compared with its golden image. SUITE is relative to the
# current source folder. On failure the HTML report (default: <binary dir>/NAME-report/index.html)
# shows expected, actual and diff images; JUnit XML goes to FILE (default:
# <binary dir>/NAME.junit.xml). Labels default to "snapshot". LAUNCHER runs the check through a
# command, e.g. `LAUNCHER ${CMAKE_COMMAND} -E env URDFSNAP_GL_BACKEND=egl` for a GL backend. The test
# checks the whole suite (--no-shard) even inside a CI job that shards (GitLab parallel:, a Slurm
# array): to split a suite over workers, run `urdfsnap snapshot check --shard` and `snapshot merge`
# directly.
# After an intended change, rewrite the goldens with `urdfsnap snapshot update SUITE`.
#
# Works in urdfsnap's own build and, through find_package(urdfsnap), in any project: it runs the
# executable target urdfsnap::urdfsnap.
function(urdfsnap_add_snapshot_test name suite)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "" "REPORT_DIR;JUNIT" "LABELS;LAUNCHER")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "urdfsnap_add_snapshot_test: unexpected arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  get_filename_component(suite "${suite}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT EXISTS "${suite}")
    message(FATAL_ERROR "urdfsnap_add_snapshot_test(${name}): no suite file ${suite}")
  endif()
  if(NOT ARG_REPORT_DIR)
    set(ARG_REPORT_DIR "${CMAKE_CURRENT_BINARY_DIR}/${name}-report")
  endif()
  if(NOT ARG_JUNIT)
    set(ARG_JUNIT "${CMAKE_CURRENT_BINARY_DIR}/${name}.junit.xml")
  endif()
  if(NOT ARG_LABELS)
    set(ARG_LABELS snapshot)
  endif()
  add_test(NAME ${name}
    COMMAND ${ARG_LAUNCHER} $<TARGET_FILE:urdfsnap::urdfsnap> snapshot check "${suite}" --no-shard
      --report "${ARG_REPORT_DIR}" --junit "${ARG_JUNIT}")
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
endfunction()
