# End-to-end tests of `voronav replay` (tests/cli_viewer.py) and of the replay page in a real
# browser (tests/browser/run.sh: Debian chromium + playwright-core from npm; label "browser").
foreach(case IN ITEMS example_and_roundtrip hand_written_recording map_only errors)
  add_test(NAME cli.viewer.${case}
           COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_viewer.py
                   $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} ${case})
  set_tests_properties(cli.viewer.${case} PROPERTIES LABELS cli TIMEOUT 120)
endforeach()
add_test(NAME cli.viewer.js_syntax
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli_viewer.py
                 $<TARGET_FILE:voronav_cli> ${PROJECT_SOURCE_DIR} js_syntax)
set_tests_properties(cli.viewer.js_syntax PROPERTIES LABELS cli TIMEOUT 60 SKIP_RETURN_CODE 77)

add_test(NAME browser.replay
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/browser/run.sh $<TARGET_FILE:voronav_cli>
                 ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(browser.replay PROPERTIES LABELS browser TIMEOUT 300)
