# Man pages made from the binary's own --help by help2man (so they never drift from it): urdfsnap(1)
# and one page per command, urdfsnap-render(1), urdfsnap-snapshot-check(1), ... gzipped and
# installed into share/man/man1. On by default when help2man is installed (scripts/deps.sh
# installs it), except in sanitizer builds; the Debian package needs them. A new command adds a
# line here; scripts/test-package.sh checks that every command `urdfsnap --help` lists has a page.
find_program(URDFSNAP_HELP2MAN help2man)
if(URDFSNAP_HELP2MAN AND NOT URDFSNAP_SANITIZE)
  set(man_default ON)
else()
  set(man_default OFF)
endif()
option(URDFSNAP_MAN_PAGES "Make man pages from --help with help2man" ${man_default})

if(URDFSNAP_MAN_PAGES)
  if(NOT URDFSNAP_HELP2MAN)
    message(FATAL_ERROR "URDFSNAP_MAN_PAGES needs help2man (apt-get install help2man)")
  endif()
  # PAGE|COMMAND WORDS|NAME LINE
  set(urdfsnap_man_pages
    "urdfsnap||RViz-like images of URDF/xacro robots, headless"
    "urdfsnap-render|render|render a robot pose to a PNG image, as RViz shows it"
    "urdfsnap-animate|animate|render a trajectory, a bag or a turntable to a video, GIF, WebP or PNG frames"
    "urdfsnap-info|info|print a robot's links, joints and tree"
    "urdfsnap-xacro|xacro|expand a xacro file to URDF"
    "urdfsnap-diff|diff|compare two PNG images with a tolerance"
    "urdfsnap-snapshot-check|snapshot check|check a snapshot suite against its golden images"
    "urdfsnap-snapshot-update|snapshot update|rewrite the golden images of a snapshot suite"
    "urdfsnap-snapshot-merge|snapshot merge|merge the results of a snapshot suite's shards"
    "urdfsnap-serve|serve|live view of a robot in the browser"
    "urdfsnap-docs|docs|write a robot's documentation page"
    "urdfsnap-dataset|dataset|render labelled samples of random poses through cameras, with COCO annotations")
  set(man_dir ${PROJECT_BINARY_DIR}/man)
  set(man_files)
  foreach(entry IN LISTS urdfsnap_man_pages)
    string(REPLACE "|" ";" fields "${entry}")
    list(GET fields 0 page)
    list(GET fields 1 words)
    list(GET fields 2 name)
    # help2man runs "BINARY WORDS --help" through the shell; the page is named after the
    # program in the version string
    add_custom_command(OUTPUT ${man_dir}/${page}.1.gz
      COMMAND ${CMAKE_COMMAND} -E make_directory ${man_dir}
      COMMAND ${URDFSNAP_HELP2MAN} --no-info --section=1 "--name=${name}"
        "--help-option=${words} --help" "--version-string=${page} ${PROJECT_VERSION}"
        --output=${man_dir}/${page}.1 $<TARGET_FILE:urdfsnap>
      COMMAND gzip -9nf ${man_dir}/${page}.1
      DEPENDS urdfsnap
      COMMENT "man page ${page}(1)"
      VERBATIM)
    list(APPEND man_files ${man_dir}/${page}.1.gz)
  endforeach()
  add_custom_target(urdfsnap_man_pages ALL DEPENDS ${man_files})
  install(FILES ${man_files} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endif()
