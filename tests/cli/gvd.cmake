# End-to-end tests of the command line: the generalized Voronoi diagram (preimage gvd). Included
# from tests/CMakeLists.txt, which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
cli_test(gvd_text 0 "gvd: 34 vertices, 36 edges \\(19 curved\\) between 5 obstacle pairs of 4 obstacles" - gvd ${EXAMPLES}/gallery.json)
cli_test(gvd_critical_points 0 "critical points of D: 8 saddles, 5 maxima" - gvd ${EXAMPLES}/gallery.json)
cli_test(gvd_resolution 0 "resolution: 2\\^-25 = 2\\.98023223877e-08 \\(input snapped to this grid\\)" - gvd ${EXAMPLES}/gallery.json)
cli_test(gvd_json 0 "\"resolution_exponent\":-25" - gvd ${EXAMPLES}/gallery.json --json)
cli_test(gvd_json_saddle 0 "\"kind\":\"plateau\"" - gvd ${EXAMPLES}/gallery.json --json)
cli_test(gvd_svg 0 "wrote .*gvd\\.svg" ${OUT}/gvd.svg gvd ${EXAMPLES}/gallery.json --svg ${OUT}/gvd.svg)
cli_test(gvd_office 0 "critical points of D: 21 saddles, 8 maxima" - gvd ${FIX}/scenes/office_walls.json)
cli_test(gvd_max_deviation 0 "curved edges sampled within 0\\.001$" - gvd ${EXAMPLES}/gallery.json --max-deviation 0.001)
cli_test(gvd_finer_than_grid fail "^preimage: gvd: snapped to the grid 2\\^1 \\(2\\), \\$\\.environment\\.obstacles\\[0\\] edge [0-9] has length 0 \\(both ends at \\(0, 0\\)\\): the input is finer than the resolution$" -
         gvd ${FIX}/scenes/gvd_finer_than_grid.json)
cli_test(gvd_no_environment fail "^preimage: .*six\\.json: the scene has no environment$" - gvd ${EXAMPLES}/landmarks/six.json)
cli_test(gvd_bad_deviation fail "--max-deviation: expected a number in \\[0, 1e\\+12\\], got -1" - gvd ${EXAMPLES}/gallery.json --max-deviation -1)
cli_test(gvd_missing_file fail "nope\\.json: cannot open file" - gvd ${FIX}/nope.json)
# --json carries what the text says: one document, the counts and the resolution, each edge's
# polyline from its 'from' vertex to its 'to' vertex, clearances as in the text.
find_package(Python3 COMPONENTS Interpreter REQUIRED)
add_test(NAME cli.gvd_json_document COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
  "d['resolution'] == 2**-25 and len(d['vertices']) == 34 and len(d['edges']) == 36 and len(d['saddles']) == 8 and len(d['maxima']) == 5 and len(d['obstacles']) == 4 and all(e['polyline'][0] == [d['vertices'][e['from']]['x'], d['vertices'][e['from']]['y']] and e['polyline'][-1] == [d['vertices'][e['to']]['x'], d['vertices'][e['to']]['y']] for e in d['edges']) and min(s['clearance'] for s in d['saddles']) == 0.5"
  -- $<TARGET_FILE:preimage_cli> gvd ${EXAMPLES}/gallery.json --json)
