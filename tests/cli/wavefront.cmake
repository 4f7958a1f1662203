# End-to-end tests of the command line: the wave-front decomposition's shortest path map
# (preimage decompose --method wavefront --start X,Y). Included from tests/CMakeLists.txt, which
# defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
cli_test(wavefront_text 0 "wavefront: shortest path map from \\(0\\.5, 7\\.5\\): 12 of 12 reflex vertices reached, D at reflex vertices from 4\\.74342 to 9\\.91261" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
cli_test(wavefront_critical_points 0 "critical points: 9 tangency bends \\(extensions to the boundary\\), 4 collisions on extensions" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
# the extension's end is the exact ray hit: (3,3) seen from (0.5,7.5) continues to y = 0 at x = 14/3
cli_test(wavefront_exact_hit 0 "bend at \\(3, 3\\) \\(D 5\\.14782\\) from \\(0\\.5, 7\\.5\\): extension to \\(4\\.66666666667, 0\\)" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
cli_test(wavefront_collision 0 "bend at \\(3, 2\\) \\(D 6\\.14782\\) from \\(3, 3\\): extension to \\(3, 0\\), collision at \\(3, 1\\.10474541314\\)" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
cli_test(wavefront_fronts_collide 0 "3 first collisions of two fronts \\(saddles of h\\)" - decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
# behind the L-shaped obstacle the fronts from its top and bottom meet on its right face
cli_test(wavefront_fronts_meet 0 "fronts from \\(6\\.2, 7\\) and \\(6\\.2, 2\\.5\\) meet at \\(6\\.2, 3\\.76779965379\\) \\(h 8\\.95409\\)" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
cli_test(wavefront_svg 0 "wrote .*wavefront\\.svg \\(regions sampled on a grid. wave fronts computed, coloured by cell\\)" ${OUT}/wavefront.svg
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5 --svg ${OUT}/wavefront.svg)
cli_test(wavefront_office 0 "critical points: 43 tangency bends \\(extensions to the boundary\\), 15 collisions on extensions" - decompose ${FIX}/scenes/office_walls.json --method wavefront --start 1,1)
cli_test(wavefront_houseexpo 0 "227 of 227 reflex vertices reached" - decompose ${OUT}/house1451.json --method wavefront --start 3,3)
set_tests_properties(cli.wavefront_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_1451)
cli_test(wavefront_no_start fail "^preimage: --method wavefront: needs --start X,Y \\(the source of the wave front\\)$" - decompose ${EXAMPLES}/gallery.json --method wavefront)
cli_test(wavefront_start_in_hole fail "^preimage: shortest path map: the source \\(2\\.5, 2\\.5\\) is not in free space$" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 2.5,2.5)
cli_test(wavefront_bad_start fail "--start: expected X,Y" - decompose ${EXAMPLES}/gallery.json --method wavefront --start 2.5)
cli_test(wavefront_start_elsewhere fail "^preimage: --start: only the wavefront decomposition has a start point$" - decompose ${EXAMPLES}/gallery.json --start 1,1)
cli_test(wavefront_angle fail "^preimage: --method wavefront: takes --start, --json and --svg only$" -
         decompose ${EXAMPLES}/gallery.json --method wavefront --start 1,1 --angle 3)
# --json carries what the text says: counts, every reflex vertex with D and predecessor, each
# tangency with its extension from the bend, the collisions.
find_package(Python3 COMPONENTS Interpreter REQUIRED)
add_test(NAME cli.wavefront_json_document COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
  "d['method'] == 'wavefront' and d['start'] == [0.5, 7.5] and d['reached'] == 12 and len(d['vertices']) == 12 and len(d['critical_points']) == 12 and sum(k['kind'] == 'fronts_collide' for k in d['critical_points']) == 3 and d['collisions_on_extensions'] == 4 and sum('collision' in k for k in d['critical_points']) == 4 and all(k['extension'][0] == k['point'] for k in d['critical_points'] if k['kind'] == 'tangency') and [4.666666666666, 0] < d['critical_points'][1]['extension'][1] < [4.666666666667, 0] and all(v['distance'] is not None for v in d['vertices']) and abs(d['distance_range'][0] - 4.743416490252569) < 1e-12"
  -- $<TARGET_FILE:preimage_cli> decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5 --json)
# The decomposition's cells and critical slices: the gallery (three obstacles) gives a Reeb
# graph with 16 cells and 14 slices, 16 - 14 + 1 = 3 independent cycles, one per obstacle.
cli_test(wavefront_cells 0 "wave-front decomposition: 16 cells, 14 critical slices" - decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
cli_test(wavefront_corner_death 0 "slice 2 at h 0\\.707107 near \\(0, 8\\): 1 cell\\(s\\) end, 0 begin" - decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5)
cli_test(wavefront_cells_houseexpo 0 "wave-front decomposition: [0-9]+ cells" - decompose ${OUT}/house0000.json --method wavefront --start 1,1)
set_tests_properties(cli.wavefront_cells_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_0000)
add_test(NAME cli.wavefront_json_cells COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
  "len(d['cells']) == 16 and len(d['nodes']) == 14 and d['nodes'][0]['level'] == 0 and d['nodes'][0]['above'] == [0] and all(c['upper'] is not None for c in d['cells']) and all(c['h'][0] <= c['h'][1] for c in d['cells']) and all(b in d['adjacency'][a] for a in range(16) for b in d['adjacency'][a])"
  -- $<TARGET_FILE:preimage_cli> decompose ${EXAMPLES}/gallery.json --method wavefront --start 0.5,7.5 --json)
# Holes touching at vertices (contacts). Checkerboard from (0.5, 0.5), on the diagonal: the
# fronts round the lower-left square reach its contact with the middle one at once from both
# free wedges and part again (a kiss: 2 cells in, 2 out); 20 cells - 16 slices + 1 = 5 holes.
cli_test(wavefront_contacts_checkerboard 0 "wave-front decomposition: 20 cells, 16 critical slices" -
         decompose ${FIX}/contacts/checkerboard.json --method wavefront --start 0.5,0.5)
cli_test(wavefront_contacts_kiss 0 "at h 2\\.58114 near \\(2[.0-9]*, 2\\): 2 cell\\(s\\) end, 2 begin" -
         decompose ${FIX}/contacts/checkerboard.json --method wavefront --start 0.5,0.5)
# two diamonds closing a corridor at three contacts: 10 cells - 9 slices + 1 = 2 holes
cli_test(wavefront_contacts_corridor 0 "wave-front decomposition: 10 cells, 9 critical slices" -
         decompose ${FIX}/contacts/corridor_closed_at_points.json --method wavefront --start 1,1)
