# The replay page (web/: three.js, bundled by esbuild) into <build>/web (index.html, app.js), which
# `mechsim view` serves. Built only where node and npm are found; web/node_modules comes from
# `npm ci` (scripts/install-deps.sh). The programs are looked for at every configure (their cache
# entries are dropped first), so that a machine that gains or loses node is never left with a
# stale "not found".
unset(MECHSIM_NODE CACHE)
unset(MECHSIM_NPM CACHE)
find_program(MECHSIM_NODE NAMES node nodejs)
find_program(MECHSIM_NPM npm)
set(web_out "${PROJECT_BINARY_DIR}/web")
set(web_src "${PROJECT_SOURCE_DIR}/web")
if(MECHSIM_NODE AND MECHSIM_NPM)
  file(GLOB web_sources CONFIGURE_DEPENDS "${web_src}/src/*.js")
  add_custom_command(
    OUTPUT "${web_out}/app.js" "${web_out}/index.html"
    COMMAND "${MECHSIM_NODE}" "${web_src}/build.mjs" "${web_out}"
    DEPENDS ${web_sources} "${web_src}/index.html" "${web_src}/build.mjs" "${web_src}/package-lock.json"
    COMMENT "Bundling the replay page (web/, esbuild)"
    VERBATIM)
  add_custom_target(mechsim_web_page ALL DEPENDS "${web_out}/app.js" "${web_out}/index.html")
  # The browser test (label web): real reports, `mechsim view`, Debian's headless Chromium.
  foreach(robot cc8 pr2)
    add_test(NAME web_replay_${robot}_test COMMAND "${MECHSIM_NODE}" "${web_src}/test/replay_test.mjs" ${robot})
    set_tests_properties(web_replay_${robot}_test PROPERTIES
      LABELS web TIMEOUT 120 SKIP_RETURN_CODE 77
      ENVIRONMENT "MECHSIM_EXE=$<TARGET_FILE:mechsim>;MECHSIM_SOURCE_DIR=${PROJECT_SOURCE_DIR};MECHSIM_PAGE_DIR=${web_out}")
  endforeach()
else()
  message(STATUS "mechsim: node/npm not found: the replay page (web/) is not built and its test skips "
                 "(scripts/install-deps.sh installs them)")
  add_test(NAME web_replay_test COMMAND sh -c "echo 'web_replay tests: skipped: node/npm were not found at configure time (scripts/install-deps.sh installs them; configure again)'; exit 77")
  set_tests_properties(web_replay_test PROPERTIES LABELS web SKIP_RETURN_CODE 77)
endif()
