# End-to-end tests of the command line: geometry, scene, render, decompose and the tool itself. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
cli_test(help 0 "Subcommands:" - --help)
cli_test(no_command fail "preimage: .*subcommand" -)
cli_test(unknown_flag fail "preimage: .*--bogus" - validate ${EXAMPLES}/gallery.json --bogus)
cli_test(validate_example 0 "ok: .*gallery.json: 20 vertices .* 3 obstacles" - validate ${EXAMPLES}/gallery.json)
cli_test(validate_names_equal_x 0 "not in general position: .* have equal x-coordinates" - validate ${FIX}/scenes/stacked_vertical_vertices.json)
cli_test(visibility_huge_coordinates fail "^preimage: \\$\\.environment\\.boundary\\[0\\]\\[0\\]: coordinate .* outside the supported range" -
         visibility ${FIX}/scenes/huge_coordinates.json --from 5,5)
cli_test(validate_json 0 "\"obstacles\":3" - validate ${EXAMPLES}/gallery.json --json)
cli_test(validate_self_intersecting fail "^preimage: \\$\\.environment\\.boundary: edges 1 and 3 intersect near \\(1, 1\\)$" -
         validate ${FIX}/scenes/self_intersecting.json)
cli_test(validate_unknown_key fail "\\$\\.environment\\.walls: unknown key" - validate ${FIX}/scenes/unknown_key.json)
cli_test(validate_syntax_error fail "syntax_error\\.json:3:33: JSON syntax error" - validate ${FIX}/scenes/syntax_error.json)
cli_test(validate_bad_coordinate fail "\\$\\.environment\\.obstacles\\[0\\]\\[2\\]\\[1\\]: expected a number" -
         validate ${FIX}/scenes/bad_coordinate.json)
cli_test(validate_missing_file fail "nope\\.json: cannot open file" - validate ${FIX}/nope.json)
cli_test(import_visilibity 0 "wrote .*: 8 vertices, 1 obstacle$" ${OUT}/pillar.json
         import ${FIX}/visilibity/room_with_pillar.txt --from visilibity -o ${OUT}/pillar.json)
cli_test(import_visilibity_bad_token fail "bad_token\\.txt:3: expected 'x y', got '10 zero'" -
         import ${FIX}/visilibity/bad_token.txt --from visilibity -o ${OUT}/never.json)
cli_test(import_unknown_format fail "--from: unknown format 'dxf'" - import ${FIX}/visilibity/bad_token.txt --from dxf -o ${OUT}/x.json)
cli_test(render 0 "wrote" ${OUT}/gallery.svg render ${EXAMPLES}/gallery.json -o ${OUT}/gallery.svg --triangulation)
cli_test(visibility_text 0 "visibility polygon from \\(1, 1\\) \\(interior\\): [0-9]+ vertices" -
         visibility ${EXAMPLES}/gallery.json --from 1,1)
cli_test(visibility_json 0 "\"kind\":\"free\"" - visibility ${EXAMPLES}/gallery.json --from 1,1 --json)
cli_test(visibility_on_edge 0 "\\(on-edge\\)" - visibility ${EXAMPLES}/gallery.json --from 12,2)
cli_test(visibility_at_vertex 0 "\\(at-vertex\\)" - visibility ${EXAMPLES}/gallery.json --from 3,3)
cli_test(visibility_svg 0 "wrote" ${OUT}/vis.svg visibility ${EXAMPLES}/gallery.json --from 1,1 --svg ${OUT}/vis.svg)
cli_test(visibility_in_obstacle fail "query point \\(2.5, 2.5\\) is not in free space: it lies inside \\$\\.environment\\.obstacles\\[0\\]$" - visibility ${EXAMPLES}/gallery.json --from 2.5,2.5)
cli_test(visibility_bad_point fail "--from: expected X,Y" - visibility ${EXAMPLES}/gallery.json --from 1:2)
cli_test(decompose_text 0 "trapezoidal decomposition: 12 cells, 14 adjacencies" - decompose ${EXAMPLES}/gallery.json)
cli_test(decompose_json 0 "\"method\":\"trapezoidal\"" - decompose ${EXAMPLES}/gallery.json --json)
cli_test(decompose_svg 0 "wrote" ${OUT}/decompose.svg decompose ${EXAMPLES}/gallery.json --svg ${OUT}/decompose.svg)
cli_test(decompose_office 0 "cells" - decompose ${FIX}/scenes/office_walls.json)
cli_test(decompose_boustrophedon 0 "10 cells \\(12 trapezoids\\), 8 critical points.*10 = 8 \\+ 3 - 1" - decompose ${EXAMPLES}/gallery.json --method boustrophedon)
cli_test(decompose_boustrophedon_angle_json 0 "\"reeb_graph\"" ${OUT}/boustrophedon.svg decompose ${FIX}/scenes/office_walls.json --method boustrophedon --angle 30 --json --svg ${OUT}/boustrophedon.svg)
cli_test(decompose_angle_needs_boustrophedon fail "--angle: the trapezoidal decomposition sweeps along x" - decompose ${EXAMPLES}/gallery.json --angle 10)
cli_test(cover_text 0 "coverage with width 0.5 \\(robot radius 0.25\\) at 0 degrees: length [0-9.]+ \\(transits [0-9.]+. bound [0-9.]+\\), [0-9]+ laps" - cover ${EXAMPLES}/gallery.json --width 0.5 --angle 0)
cli_test(cover_auto_json_svg 0 "\"laps\"" ${OUT}/cover.svg cover ${EXAMPLES}/gallery.json --width 0.5 --angle auto --json --svg ${OUT}/cover.svg)
cli_test(cover_bad_width fail "--width: expected a number in \\(0, 1e\\+12\\], got -1" - cover ${EXAMPLES}/gallery.json --width -1)
cli_test(cover_width_defaults_to_2r 0 "coverage with width 0.6 \\(robot radius 0.3\\)" - cover ${EXAMPLES}/gallery.json --radius 0.3)
cli_test(cover_needs_width_or_radius fail "--width: not given, and without a robot radius" - cover ${FIX}/scenes/step_in_the_floor.json)
cli_test(cover_start_too_close_to_a_wall fail "start \\(0.02, 4\\) is 0.02 from an obstacle: a robot of radius 0.25 does not fit there" -
         cover ${EXAMPLES}/gallery.json --radius 0.25 --start 0.02,4)
cli_test(cover_dfs_decomposition 0 "coverage with width 0.5" - cover ${EXAMPLES}/gallery.json --width 0.5 --order dfs --transit decomposition)
cli_test(plan_robot_radius 0 "path from \\(1, 1\\) to \\(11, 7\\) for a robot of radius 0.4: [0-9]+ points, length [0-9.]+ \\(every segment certified\\)" -
         plan ${EXAMPLES}/gallery.json --radius 0.4)
cli_test(plan_trapezoidal 0 "through [0-9]+ of [0-9]+ cells" - plan ${EXAMPLES}/gallery.json --method trapezoidal)
cli_test(plan_no_shorten_needs_trapezoidal fail "--no-shorten: applies to --method trapezoidal only" - plan ${EXAMPLES}/gallery.json --no-shorten)
cli_test(cover_bad_angle fail "--angle: expected degrees or 'auto', got 'north'" - cover ${EXAMPLES}/gallery.json --width 1 --angle north)
cli_test(decompose_stacked_vertices 0 "N_cells = N_critical \\+ N_obstacles - 1: ([0-9]+) = " - decompose ${FIX}/scenes/stacked_vertical_vertices.json --method boustrophedon)
cli_test(cover_stacked_vertices 0 "coverage with width 0.3" - cover ${FIX}/scenes/stacked_vertical_vertices.json --width 0.3)
cli_test(plan_stacked_vertices 0 "path from \\(0.5, 0.5\\) to \\(5.5, 5.5\\)" - plan ${FIX}/scenes/stacked_vertical_vertices.json)
cli_test(decompose_unknown_method fail "--method" - decompose ${EXAMPLES}/gallery.json --method voronoi)
cli_test(plan_scene_start_goal 0 "path from \\(1, 1\\) to \\(11, 7\\) for a robot of radius 0.25: [0-9]+ points" - plan ${EXAMPLES}/gallery.json)
cli_test(plan_flags_json 0 "\"found\":true" ${OUT}/plan.svg plan ${EXAMPLES}/gallery.json --start 0.5,7.5 --goal 11.5,0.5 --json --svg ${OUT}/plan.svg)
cli_test(plan_start_in_obstacle fail "start \\(2.5, 2.5\\) is not in free space: it lies inside \\$\\.environment\\.obstacles\\[0\\]" -
         plan ${EXAMPLES}/gallery.json --start 2.5,2.5)
cli_test(demo 0 "index\\.html" ${OUT}/demo/index.html demo --out ${OUT}/demo)
# The interactive report in a real (headless) browser: its script runs without an error,
# every figure zooms and resets, every step slider moves its paths.
set_tests_properties(cli.demo PROPERTIES FIXTURES_SETUP demo_report)
add_test(NAME cli.demo_in_browser COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/browser_check.sh ${OUT}/demo/index.html)
set_tests_properties(cli.demo_in_browser PROPERTIES FIXTURES_REQUIRED demo_report)
# ... and the check can fail: the same report with a call to an undefined function
# slipped into its script.
add_test(NAME cli.browser_check_catches_a_script_error
         COMMAND ${EXPECT} fail "data-script-errors=.*undefinedFunctionOfTheTest" - -- bash -c
                 "sed '/var figures = /i undefinedFunctionOfTheTest()' \"$0\" > \"$1\" && \"$2\" \"$1\""
                 ${OUT}/demo/index.html ${OUT}/broken_report.html ${CMAKE_CURRENT_SOURCE_DIR}/cli/browser_check.sh)
set_tests_properties(cli.browser_check_catches_a_script_error PROPERTIES FIXTURES_REQUIRED demo_report)

# GeoJSON and WKT in, GeoJSON out (issue 22).
cli_test(import_wkt 0 "wrote .*: 10 vertices, 1 obstacle" ${OUT}/l_room_wkt.json import ${EXAMPLES}/formats/l_room.wkt --from wkt -o ${OUT}/l_room_wkt.json)
cli_test(import_geojson 0 "wrote .*: 10 vertices, 1 obstacle" ${OUT}/l_room_geojson.json import ${EXAMPLES}/formats/l_room.geojson --from geojson -o ${OUT}/l_room_geojson.json)
cli_test(import_unknown_format_lists_all fail "--from: unknown format 'shp' \\(expected houseexpo, visilibity, geojson or wkt\\)" - import ${EXAMPLES}/formats/l_room.wkt --from shp -o ${OUT}/never.json)
cli_test(visibility_geojson 0 "wrote .*vis\\.geojson" ${OUT}/vis.geojson visibility ${EXAMPLES}/gallery.json --from 1,1 --geojson ${OUT}/vis.geojson)
cli_test(plan_geojson 0 "wrote .*plan\\.geojson" ${OUT}/plan.geojson plan ${EXAMPLES}/gallery.json --radius 0.2 --geojson ${OUT}/plan.geojson)
cli_test(cover_geojson 0 "wrote .*cover\\.geojson" ${OUT}/cover.geojson cover ${EXAMPLES}/gallery.json --radius 0.2 --geojson ${OUT}/cover.geojson)
cli_test(decompose_geojson 0 "wrote .*cells\\.geojson" ${OUT}/cells.geojson decompose ${EXAMPLES}/gallery.json --method boustrophedon --geojson ${OUT}/cells.geojson)

# Real floor plans (HouseExpo, shipped in examples/floorplans).
cli_test(import_houseexpo_0000 0 "wrote .*: 147 vertices" ${OUT}/house0000.json
         import ${FLOORPLANS}/house_expo_room_0000.json --from houseexpo -o ${OUT}/house0000.json)
cli_test(import_houseexpo_1451 0 "wrote .*: 434 vertices" ${OUT}/house1451.json
         import ${FLOORPLANS}/house_expo_room_1451.json --from houseexpo -o ${OUT}/house1451.json)
cli_test(validate_imported_houseexpo 0 "ok: .*147 vertices" - validate ${OUT}/house0000.json)
set_tests_properties(cli.validate_imported_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_0000)
cli_test(visibility_houseexpo 0 "\"location\":\"interior\"" - visibility ${OUT}/house1451.json --from 3,3 --json)
set_tests_properties(cli.visibility_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_1451)
cli_test(decompose_houseexpo 0 "26 cells \\(225 trapezoids\\), 27 critical points" - decompose ${OUT}/house1451.json --method boustrophedon)
cli_test(plan_houseexpo 0 "path from \\(1, 1\\) to \\(9, 7\\)" - plan ${OUT}/house1451.json --start 1,1 --goal 9,7)
cli_test(cover_houseexpo 0 "coverage with width 0.4 at" - cover ${OUT}/house1451.json --width 0.4 --angle auto)
# Issue 24's report: at width 0.3 from (1, 1) the path left the boundary by up to 5 mm.
cli_test(cover_houseexpo_1451_corners_inside 0 "covered (99\\.[5-9][0-9]*|100)% of the configuration space"
         - cover ${OUT}/house1451.json --width 0.3 --start 1,1)
set_tests_properties(cli.decompose_houseexpo cli.plan_houseexpo cli.cover_houseexpo cli.cover_houseexpo_1451_corners_inside
                     PROPERTIES DEPENDS cli.import_houseexpo_1451)

# Issue 23: every command line of README.md and docs/*.md (```sh blocks) and every example in
# a subcommand's --help runs as written on the shipped files, so none can drift.
add_test(NAME cli.doc_examples COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/doc_examples.sh ${PROJECT_SOURCE_DIR} $<TARGET_FILE:preimage_cli> docs)
add_test(NAME cli.help_examples COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/doc_examples.sh ${PROJECT_SOURCE_DIR} $<TARGET_FILE:preimage_cli> help)
# JSON is one compact line by default; --pretty indents it and keeps short arrays on a line.
cli_test(json_compact_by_default 0 "^\\{\"[a-z_]+\":.*\\}$" - validate ${EXAMPLES}/gallery.json --json)
cli_test(json_pretty 0 "^  \"[a-z_]+\": " - validate ${EXAMPLES}/gallery.json --pretty)

# Issue 26: a tiny tool width implied billions of laps (and the lap placement was quadratic
# in them); widths below 1e-5 of the environment's diameter are refused up front.
cli_test(cover_width_1e-9_refused fail "--width 1e-09: the environment is .* across, which needs more than 100000 laps" -
         cover ${EXAMPLES}/gallery.json --width 1e-9)
cli_test(cover_width_1e-3_many_laps 0 "16[0-9]{3} laps" - cover ${EXAMPLES}/gallery.json --width 1e-3 --angle 0)

# Issue 23: a misspelled command is named, with the closest commands.
cli_test(unknown_command_did_you_mean fail "unknown command 'visiblity' for 'preimage'. did you mean 'visibility'\\?" -
         visiblity ${EXAMPLES}/gallery.json --from 1,1)
cli_test(unknown_subcommand_did_you_mean fail "unknown command 'navigte' for 'preimage landmarks'. did you mean 'navigate'\\?" -
         landmarks navigte ${EXAMPLES}/gallery.json)
cli_test(unknown_command_lists_commands fail "unknown command 'xyzzy' for 'preimage'. commands: .*visibility" - xyzzy)
cli_test(import_plural_obstacles 0 "wrote .*: 147 vertices, 0 obstacles" ${OUT}/house0000_plural.json
         import ${FLOORPLANS}/house_expo_room_0000.json --from houseexpo -o ${OUT}/house0000_plural.json)

# Issue 26: file names that are not UTF-8 went through JSON unescaped (internal error).
add_test(NAME cli.non_utf8_file_names COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cli/non_utf8_name.sh $<TARGET_FILE:preimage_cli> ${FIX} ${OUT}/non-utf8)
# Issue 26: a number beyond the range of doubles was an internal error; now an input error naming its JSON path.
cli_test(import_houseexpo_number_overflow fail "number_overflow\\.json: \\$\\.verts\\[2\\]\\[1\\]: number 1e400 is outside the range of doubles$" -
         import ${FIX}/houseexpo/number_overflow.json --from houseexpo -o ${OUT}/never.json)
cli_test(validate_number_overflow fail "\\$\\.environment\\.boundary\\[1\\]\\[0\\]: number -1e400 is outside the range of doubles$" -
         validate ${FIX}/scenes/number_overflow.json)
cli_test(import_houseexpo 0 "wrote .*: 6 vertices, 0 obstacles" ${OUT}/l_shape.json import ${FIX}/houseexpo/l_shape.json --from houseexpo -o ${OUT}/l_shape.json)
cli_test(import_missing_file fail "nope\\.json: cannot open file$" - import ${FIX}/nope.json --from houseexpo -o ${OUT}/never.json)

# Holes touching at vertices (issue 29): accepted by every command that takes an environment
# (pursuit says it does not support them yet), a point robot passes a contact, a disc not.
set(CONTACTS ${FIX}/contacts)
cli_test(contacts_validate 0 "3 obstacles|2 obstacles, free area 18, 3 contacts .rings touching at a vertex." - validate ${CONTACTS}/corridor_closed_at_points.json)
cli_test(contacts_visibility_at_contact 0 "from .5, 1. .at-vertex.: 14 vertices, 10 solid and 4 free edges, area 16" - visibility ${CONTACTS}/corridor_closed_at_points.json --from 5,1)
cli_test(contacts_plan_point_robot_through_contacts 0 "2 points, length 8 .every segment certified" - plan ${CONTACTS}/corridor_closed_at_points.json --radius 0)
cli_test(contacts_plan_trapezoidal_through_contacts 0 "length 8, through 4 of 8 cells" - plan ${CONTACTS}/corridor_closed_at_points.json --radius 0 --method trapezoidal)
cli_test(contacts_plan_disc_robot_blocked 0 "no path .* different components of the configuration space" - plan ${CONTACTS}/corridor_closed_at_points.json --radius 0.05)
cli_test(contacts_boustrophedon_euler 0 "N_cells = N_critical \\+ N_obstacles - 1 - N_merges: 6 = 6 \\+ 5 - 1 - 4" - decompose ${CONTACTS}/checkerboard.json --method boustrophedon)
cli_test(contacts_cover 0 "covered 100% of the configuration space" - cover ${CONTACTS}/checkerboard.json --width 0.2 --radius 0)
cli_test(contacts_overlap_rejected fail "obstacles.1. vertex 0 and .*obstacles.0. vertex 2 overlap at .4, 4." - validate ${CONTACTS}/overlap_at_contact.json)
# Pursuit with contacts: rays where a contact point's visibility changes; the pocket under
# the chevron is reached only through contact points, which the search's pursuers do not
# pass (so "no plan" says so), while the checker follows a pursuer through one.
cli_test(contacts_pursuit_cells 0 "28 critical segments .24 edge extensions, 48 bitangent rays, 24 contact rays, 28 segments where rays coincide., 28 cells" -
         pursuit cells ${CONTACTS}/checkerboard.json)
cli_test(contacts_pursuit_pocket_no_plan_avoiding_contacts 0 "no plan with 2 pursuers waiting at cell samples on paths that avoid contact points" -
         pursuit plan ${CONTACTS}/pocket_under_chevron.json --pursuers 2)
cli_test(contacts_pursuit_pocket_entered_through_contact 0 "2 pursuers, 3 waypoints: cleared .from waypoint 1 on." -
         pursuit check ${CONTACTS}/pocket_under_chevron.json --path ${CONTACTS}/pocket_under_chevron_path.json)
cli_test(contacts_pursuit_pocket_recontaminated_alone 0 "NOT cleared: 1 region contaminated at the end .area 10." -
         pursuit check ${CONTACTS}/pocket_under_chevron.json --path ${CONTACTS}/pocket_under_chevron_alone.json)

# Issue 29: range-limited visibility, batches of viewpoints, full visibility graphs.
cli_test(visibility_range_text 0 "visibility from \\(4, 4\\) \\(interior\\) within range 3: [0-9]+ segments and [0-9]+ arcs, area [0-9.]+ \\(unlimited: [0-9.]+\\)" -
         visibility ${EXAMPLES}/gallery.json --from 4,4 --range 3)
cli_test(visibility_range_json 0 "\"kind\":\"arc\".*\"kind\":\"circle-crossing\"|\"kind\":\"circle-crossing\".*\"kind\":\"arc\"" -
         visibility ${EXAMPLES}/gallery.json --from 4,4 --range 3 --json)
cli_test(visibility_range_whole_disc 0 "within range 0\\.5: the whole disc, area 0\\.785" - visibility ${EXAMPLES}/gallery.json --from 1,1 --range 0.5)
cli_test(visibility_range_huge_is_v 0 "within range 1000: [0-9]+ segments and 0 arcs, area ([0-9.]+) \\(unlimited: \\1\\)" -
         visibility ${EXAMPLES}/gallery.json --from 1,1 --range 1000)
cli_test(visibility_range_at_vertex 0 "\\(at-vertex\\) within range 2: " - visibility ${EXAMPLES}/gallery.json --from 3,3 --range 2)
cli_test(visibility_range_svg_arcs 0 "wrote .*range\\.svg" ${OUT}/range.svg visibility ${EXAMPLES}/gallery.json --from 4,4 --range 3 --svg ${OUT}/range.svg)
add_test(NAME cli.visibility_range_svg_has_arcs COMMAND grep -Eq "<path d=\"M[0-9.,]+ .*A[0-9.]+,[0-9.]+ 0 [01] 0 " ${OUT}/range.svg)
set_tests_properties(cli.visibility_range_svg_has_arcs PROPERTIES DEPENDS cli.visibility_range_svg_arcs)
cli_test(visibility_range_geojson 0 "wrote .*range\\.geojson" ${OUT}/range.geojson visibility ${EXAMPLES}/gallery.json --from 4,4 --range 3 --geojson ${OUT}/range.geojson)
cli_test(visibility_range_zero fail "--range: expected a number in \\(0, 1e\\+12\\], got 0" - visibility ${EXAMPLES}/gallery.json --from 1,1 --range 0)
cli_test(visibility_range_not_a_number fail "--range" - visibility ${EXAMPLES}/gallery.json --from 1,1 --range far)
cli_test(visibility_range_in_obstacle fail "query point \\(2.5, 2.5\\) is not in free space: it lies inside \\$\\.environment\\.obstacles\\[0\\]$" -
         visibility ${EXAMPLES}/gallery.json --from 2.5,2.5 --range 1)
cli_test(visibility_points_batch 0 "^\\{\"area\":.*\"line\":8,.*\\}$" - visibility ${EXAMPLES}/gallery.json --points ${EXAMPLES}/gallery_points.txt)
cli_test(visibility_points_batch_range 0 "\"line\":8,.*\"range\":2.5" - visibility ${EXAMPLES}/gallery.json --points ${EXAMPLES}/gallery_points.txt --range 2.5)
cli_test(visibility_points_bad_token fail "bad_token\\.txt:3: expected 'x y' \\(two numbers\\), got 'zero'$" -
         visibility ${EXAMPLES}/gallery.json --points ${FIX}/points/bad_token.txt)
# JSON Lines: one record per point (six in the file), and the records before a bad line are out.
add_test(NAME cli.visibility_points_one_record_per_point
         COMMAND bash -c "\"$0\" visibility \"$1\" --points \"$2\" | grep -c '^{.*\"line\":[0-9]*,.*}$'"
                 $<TARGET_FILE:preimage_cli> ${EXAMPLES}/gallery.json ${EXAMPLES}/gallery_points.txt)
set_tests_properties(cli.visibility_points_one_record_per_point PROPERTIES PASS_REGULAR_EXPRESSION "^6\n$")
add_test(NAME cli.visibility_points_records_before_a_bad_line
         COMMAND bash -c "\"$0\" visibility \"$1\" --points \"$2\" 2>/dev/null | grep -c '\"line\":[12],'"
                 $<TARGET_FILE:preimage_cli> ${EXAMPLES}/gallery.json ${FIX}/points/bad_token.txt)
set_tests_properties(cli.visibility_points_records_before_a_bad_line PROPERTIES PASS_REGULAR_EXPRESSION "^2\n$")
cli_test(visibility_points_three_numbers fail "three_numbers\\.txt:3: expected 'x y' \\(two numbers\\), got 3 tokens \\(extra '5'\\)$" -
         visibility ${EXAMPLES}/gallery.json --points ${FIX}/points/three_numbers.txt --range 1)
cli_test(visibility_points_in_obstacle fail "in_obstacle\\.txt:3: .*query point \\(2.5, 2.5\\) is not in free space: it lies inside \\$\\.environment\\.obstacles\\[0\\]$" -
         visibility ${EXAMPLES}/gallery.json --points ${FIX}/points/in_obstacle.txt)
cli_test(visibility_points_missing_file fail "nope\\.txt: cannot open file$" - visibility ${EXAMPLES}/gallery.json --points ${FIX}/points/nope.txt)
cli_test(visibility_needs_from_or_points fail "--from or --points: give one viewpoint" - visibility ${EXAMPLES}/gallery.json)
cli_test(visibility_from_excludes_points fail "--from excludes --points|--points excludes --from" - visibility ${EXAMPLES}/gallery.json --from 1,1 --points ${EXAMPLES}/gallery_points.txt)
cli_test(visibility_points_no_svg fail "--svg: draws one viewpoint \\(--from\\), not a batch \\(--points\\)" -
         visibility ${EXAMPLES}/gallery.json --points ${EXAMPLES}/gallery_points.txt --svg ${OUT}/never.svg)
cli_test(visibility_graph_vertex 0 "^vertex-vertex visibility graph: 20 vertices, [0-9]+ edges$" - visibility-graph ${EXAMPLES}/gallery.json)
cli_test(visibility_graph_points_json 0 "\"kind\":\"point-point\".*\"points\":\\[\\[1(\\.0)?,1(\\.0)?\\]" - visibility-graph ${EXAMPLES}/gallery.json --points ${EXAMPLES}/gallery_points.txt --json)
cli_test(visibility_graph_point_vertex_svg 0 "point-vertex visibility graph: 20 vertices and 6 points, [0-9]+ edges" ${OUT}/graph.svg
         visibility-graph ${EXAMPLES}/gallery.json --points ${EXAMPLES}/gallery_points.txt --kind point-vertex --svg ${OUT}/graph.svg)
cli_test(visibility_graph_unknown_kind fail "--kind: unknown graph 'edge' \\(expected vertex, point or point-vertex\\)" -
         visibility-graph ${EXAMPLES}/gallery.json --kind edge)
cli_test(visibility_graph_kind_needs_points fail "--kind point-vertex: needs --points FILE" - visibility-graph ${EXAMPLES}/gallery.json --kind point-vertex)
cli_test(visibility_graph_vertex_takes_no_points fail "--points: the vertex graph joins environment vertices only" -
         visibility-graph ${EXAMPLES}/gallery.json --kind vertex --points ${EXAMPLES}/gallery_points.txt)
cli_test(visibility_graph_point_in_obstacle fail "in_obstacle\\.txt:3: point \\(2.5, 2.5\\) is not in free space: it lies inside \\$\\.environment\\.obstacles\\[0\\]$" -
         visibility-graph ${EXAMPLES}/gallery.json --points ${FIX}/points/in_obstacle.txt)
cli_test(visibility_graph_bad_token fail "bad_token\\.txt:3: expected 'x y' \\(two numbers\\), got 'zero'$" -
         visibility-graph ${EXAMPLES}/gallery.json --points ${FIX}/points/bad_token.txt)
# Overlapping wall rectangles: an error naming both, or their union with --merge-holes (the
# two that only touch at (7, 2) stay two obstacles with a contact).
cli_test(import_overlapping_holes_rejected fail "holes.1. edge .* touches holes.0. edge" - import ${CONTACTS}/overlapping_walls.wkt --from wkt -o ${OUT}/overlapping_walls.json)
cli_test(import_merge_holes 0 "wrote .*: 19 vertices, 3 obstacles, 1 contact" ${OUT}/merged_walls.json import ${CONTACTS}/overlapping_walls.wkt --from wkt --merge-holes -o ${OUT}/merged_walls.json)
# Variable slices (6.2.3): decompositions around a centre and their coverage patterns.
cli_test(decompose_circular 0 "circular decomposition around \\(6.1, 4.05\\): 22 cells, 20 critical points in 20 critical slices" ${OUT}/circular.svg
         decompose ${EXAMPLES}/gallery.json --method circular --center 6.1,4.05 --svg ${OUT}/circular.svg)
cli_test(decompose_spike_json 0 "\"method\":\"spike\".*\"reeb_graph\"" - decompose ${EXAMPLES}/gallery.json --method spike --center 6.1,4.05 --json)
cli_test(decompose_squarel_geojson 0 "wrote .*squarel\\.geojson" ${OUT}/squarel.geojson
         decompose ${EXAMPLES}/gallery.json --method squarel --geojson ${OUT}/squarel.geojson)
cli_test(decompose_centre_on_boundary fail "--center \\(0, 4\\) lies on the boundary" - decompose ${EXAMPLES}/gallery.json --method spike --center 0,4)
cli_test(decompose_centre_needs_variable_slice fail "--center: only the circular, spike and squarel decompositions have a centre" -
         decompose ${EXAMPLES}/gallery.json --center 1,1)
cli_test(decompose_bad_centre fail "--center: expected X,Y" - decompose ${EXAMPLES}/gallery.json --method squarel --center 1,x)
cli_test(cover_spiral 0 "covered (99\\.[0-9]+|100)% of the configuration space" ${OUT}/spiral.svg
         cover ${EXAMPLES}/gallery.json --pattern spiral --center 6.1,4.05 --radius 0.2 --svg ${OUT}/spiral.svg)
cli_test(cover_spike_json 0 "\"pattern\":\"spike\"" - cover ${EXAMPLES}/gallery.json --pattern spike --radius 0.2 --json)
cli_test(cover_pattern_no_angle fail "--angle: only the boustrophedon pattern has a sweep direction" - cover ${EXAMPLES}/gallery.json --pattern spike --radius 0.2 --angle 30)
cli_test(cover_squarel_houseexpo 0 "covered (99\\.[0-9]+|100)% of the configuration space" - cover ${OUT}/house1451.json --pattern squarel --width 0.3 --radius 0.15)
cli_test(decompose_circular_houseexpo 0 "circular decomposition around" - decompose ${OUT}/house0000.json --method circular)
set_tests_properties(cli.cover_squarel_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_1451)
set_tests_properties(cli.decompose_circular_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_0000)
# Brushfire (6.2.3): the distance to the obstacles, its cells and the offset pattern.
cli_test(decompose_brushfire 0 "brushfire decomposition: 15 cells, 8 saddles and 6 maxima of D in 12 critical slices" ${OUT}/brushfire.svg
         decompose ${EXAMPLES}/gallery.json --method brushfire --svg ${OUT}/brushfire.svg)
cli_test(decompose_brushfire_json 0 "\"method\":\"brushfire\".*\"reeb_graph\"" - decompose ${EXAMPLES}/gallery.json --method brushfire --json)
cli_test(decompose_brushfire_no_angle fail "--angle: the brushfire decomposition has no sweep direction" - decompose ${EXAMPLES}/gallery.json --method brushfire --angle 30)
cli_test(decompose_brushfire_houseexpo 0 "brushfire decomposition: 19 cells" ${OUT}/brushfire1451.geojson
         decompose ${OUT}/house1451.json --method brushfire --geojson ${OUT}/brushfire1451.geojson)
cli_test(cover_brushfire_houseexpo 0 "covered (99\\.[0-9]+|100)% of the configuration space" - cover ${OUT}/house0000.json --pattern brushfire --width 0.3 --radius 0.15)
cli_test(cover_brushfire_contacts 0 "covered (99\\.[0-9]+|100)% of the configuration space" - cover ${FIX}/contacts/checkerboard.json --pattern brushfire --width 0.2 --radius 0)
cli_test(cover_brushfire_no_centre fail "--center: the brushfire pattern grows from the obstacles, it has no centre" -
         cover ${EXAMPLES}/gallery.json --pattern brushfire --radius 0.2 --center 1,1)
cli_test(cover_wavefront_houseexpo 0 "covered (99\\.[0-9]+|100)% of the configuration space" - cover ${OUT}/house1451.json --pattern wavefront --width 0.3 --radius 0.15 --start 1,1)
cli_test(cover_wavefront_needs_start fail "the wavefront pattern needs a start \\(the tether's anchor\\): --start X,Y" - cover ${FIX}/morse/circle_through_vertex.json --pattern wavefront --width 0.2 --radius 0)
set_tests_properties(cli.cover_wavefront_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_1451)
# A hall of 240 pillars, 1,013 vertices (issue 49's "1,000-vertex map"): the wave front
# sampled by roots covers it (2.6 s at W = 1; 68.6 s at W = 0.5 before, 6.8 s now: docs/coverage.md).
cli_test(cover_wavefront_pillared_hall 0 "covered (99\\.[5-9][0-9]*|100)% of the configuration space" -
         cover ${FIX}/coverage/pillared_hall_1000.json --pattern wavefront --width 1 --radius 0.5 --start 1,1)
set_tests_properties(cli.decompose_brushfire_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_1451)
set_tests_properties(cli.cover_brushfire_houseexpo PROPERTIES DEPENDS cli.import_houseexpo_0000)
cli_test(decompose_circular_contacts 0 "circular decomposition around \\(2.5, 0.5\\): 19 cells" - decompose ${FIX}/contacts/checkerboard.json --method circular --center 2.5,0.5)
cli_test(cover_spiral_contacts 0 "covered (99\\.[0-9]+|100)% of the configuration space" - cover ${FIX}/contacts/checkerboard.json --pattern spiral --width 0.2 --radius 0 --center 2.5,0.5)
# cover --online (6.2.4): the robot builds the Reeb graph as it covers; compared with the offline graph.
cli_test(cover_online_gallery 0 "complete: every critical point has all its edges explored" - cover ${EXAMPLES}/gallery.json --radius 0.2 --online --angle 17)
cli_test(cover_online_isomorphic 0 "offline boustrophedon Reeb graph: 8 critical slices, 10 cells: isomorphic" - cover ${EXAMPLES}/gallery.json --radius 0.2 --online --angle 17)
cli_test(cover_online_json_svg 0 "\"isomorphic\":true" ${OUT}/cover_online.svg cover ${EXAMPLES}/gallery.json --radius 0.2 --online --angle 17 --json --svg ${OUT}/cover_online.svg)
cli_test(cover_online_raster_misses_ceiling_cp 0 "differs: offline critical slice 1 .* was never sensed" - cover ${FIX}/online/ceiling_critical_point.json --online --raster --angle 13)
cli_test(cover_online_cycle_finds_ceiling_cp 0 "4 critical slices, 4 cells: isomorphic" - cover ${FIX}/online/ceiling_critical_point.json --online --angle 13)
cli_test(cover_online_several_critical_points_in_one_strip 0 "offline boustrophedon Reeb graph: 10 critical slices, 12 cells: isomorphic"
         - cover ${FIX}/online/several_critical_points_in_one_strip.json --online --angle 33)
cli_test(cover_online_obstacles_starting_on_one_slice 0 "slice at .* \\(1 cells left, 3 right\\)"
         - cover ${FIX}/online/obstacles_starting_on_one_slice.json --online --angle 0)
cli_test(cover_online_obstacles_starting_on_one_slice_isomorphic 0 "offline boustrophedon Reeb graph: 4 critical slices, 5 cells: isomorphic"
         - cover ${FIX}/online/obstacles_starting_on_one_slice.json --online --angle 0)
cli_test(cover_online_wide_tool fail "^preimage: --width 0.5: online coverage needs 0 < w <= 2r = 0.4" - cover ${EXAMPLES}/gallery.json --radius 0.2 --width 0.5 --online)
cli_test(cover_online_bad_sensors fail "^preimage: --sensors 10: the ring needs a multiple of 4 sensors" - cover ${EXAMPLES}/gallery.json --radius 0.2 --online --sensors 10)
cli_test(cover_online_flags_need_online fail "^preimage: --sensors/--range/--noise/--raster: only with --online" - cover ${EXAMPLES}/gallery.json --radius 0.2 --noise 0.1)
# A tool wider than the plan (issue 47): the metrics' raster had no sample in the free space and
# said "covered 0%" while the path covered everything; brushfire's path is the start alone and
# wave-front refused. Every pattern must now report the whole configuration space covered.
# Labelled degenerate: cheap, but they skip the patterns' lap code, so CI's sanitizer subset
# (scripts/sanitize-subset) picks another test of each pattern.
foreach(pattern boustrophedon brushfire wavefront spiral spike concentric squarel)
  cli_test(cover_huge_width_metrics_${pattern} 0 "covered 100% of the configuration space" -
           cover ${EXAMPLES}/gallery.json --width 1e12 --pattern ${pattern})
  set_tests_properties(cli.cover_huge_width_metrics_${pattern} PROPERTIES LABELS degenerate)
endforeach()
cli_test(cover_huge_width_wavefront_anchor_alone 0 "wavefront pattern: length 0 \\(transits 0. bound [0-9.]+\\), 0 laps" -
         cover ${EXAMPLES}/gallery.json --width 1e3 --pattern wavefront --start 1,1)
set_tests_properties(cli.cover_huge_width_wavefront_anchor_alone PROPERTIES LABELS degenerate)

# export (issue 47): GeoJSON and WKT out; exported, imported and exported again: the same text.
cli_test(export_geojson 0 "wrote .*pillar\\.geojson: 8 vertices, 1 obstacle" ${OUT}/pillar.geojson
         export ${EXAMPLES}/pursuit/pillar.json --to geojson -o ${OUT}/pillar.geojson)
cli_test(export_wkt_stdout 0 "^POLYGON \\(\\(0 0, 6 0, 6 6, 0 6, 0 0\\), \\(" - export ${EXAMPLES}/pursuit/pillar.json --to wkt)
cli_test(export_unknown_format fail "--to: unknown format 'shp' \\(expected geojson or wkt\\)" - export ${EXAMPLES}/pursuit/pillar.json --to shp)
cli_test(export_no_environment fail "the scene has no environment" - export ${EXAMPLES}/landmarks/six.json --to wkt)
foreach(format geojson wkt)
  add_test(NAME cli.export_${format}_round_trip
           COMMAND ${EXPECT} 0 "^same$" - -- bash -c
                   "\"$0\" export \"$1\" --to ${format} -o \"$2.a\" >/dev/null && \"$0\" import \"$2.a\" --from ${format} -o \"$2.json\" >/dev/null && \"$0\" export \"$2.json\" --to ${format} -o \"$2.b\" >/dev/null && cmp \"$2.a\" \"$2.b\" && echo same"
                   $<TARGET_FILE:preimage_cli> ${OUT}/house1451.json ${OUT}/export-round-trip-${format})
  set_tests_properties(cli.export_${format}_round_trip PROPERTIES DEPENDS cli.import_houseexpo_1451)
endforeach()
cli_test(cover_wide_wavefront_still_needs_fronts 0 "covered (99\\.[5-9][0-9]*|100)% of the configuration space" -
         cover ${EXAMPLES}/gallery.json --width 8 --pattern wavefront --start 0.5,7.5)
# A room 2e-6 across at --width 1e12 (review of issue 47): w/2 over the raster's cell
# overflowed a long when cast, no row was scanned, and the metrics said 0%.
foreach(pattern boustrophedon brushfire)
  cli_test(cover_huge_width_tiny_room_${pattern} 0 "covered 100% of the configuration space" -
           cover ${FIX}/scenes/tiny_room_2e-6.json --width 1e12 --radius 0 --pattern ${pattern} --start 1e-7,1e-7)
  set_tests_properties(cli.cover_huge_width_tiny_room_${pattern} PROPERTIES LABELS degenerate)
endforeach()

# Issue 49: every geometric command on a real plan at the origin and shifted to UTM, Web
# Mercator, 1e10 and just inside 1e12 gives the origin's answer moved; 1e12 is refused.
cli_test(cover_far_from_the_origin_keeps_its_area 0 "covered (100|99\\.9[0-9]*)% of the configuration space \\(84\\.0420140764 m2\\)" -
         cover ${FIX}/scenes/room_with_hole_at_1e10.json --radius 0.25)
cli_test(cover_spiral_far_from_the_origin 0 "spiral pattern: length 281\\.267463895.*19 touch-ups" - cover ${FIX}/scenes/room_with_hole_at_1e10.json --radius 0.25 --pattern spiral)
cli_test(cover_far_from_the_origin_names_the_start_as_given fail "start \\(10000000005, 10000000005\\) is not in free space" -
         cover ${FIX}/scenes/room_with_hole_at_1e10.json --radius 0.25 --start 10000000005,10000000005)
# Rounding back put the path's corner point on the hole's corner (r = 1e-7 at 1e10): pushed
# out in the direction taken in the local frame, not from the rounded point (internal error).
cli_test(plan_far_from_the_origin_tiny_robot_rounds_off_a_corner 0 "for a robot of radius 1e-07: 9 points.*every segment certified" -
         plan ${FIX}/scenes/room_with_hole_at_1e10.json --start 10000000001,10000000001 --goal 10000000009,10000000009 --radius 1e-7)
find_package(Python3 COMPONENTS Interpreter REQUIRED)
add_test(NAME cli.translation_invariance COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/translation_invariance.py
         $<TARGET_FILE:preimage_cli> ${PROJECT_SOURCE_DIR}/examples/floorplans/office_mlstruct_302.json ${CMAKE_CURRENT_BINARY_DIR}/translation-scratch)

# Issue 49: every coverage pattern covers >= 99.5 % of the configuration space on the four
# real plans and on random rooms with holes, by an independent area check (shapely).
# Debian's interpreter (Python_EXECUTABLE, as for the module), where install-deps --test
# puts python3-shapely (a python3 earlier on PATH, such as pyenv's, need not have it).
add_test(NAME cli.pattern_completeness COMMAND ${Python_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/pattern_completeness.py
         $<TARGET_FILE:preimage_cli> ${CMAKE_CURRENT_BINARY_DIR}/completeness-scratch
         ${FLOORPLANS}/house_expo_room_0000.json ${FLOORPLANS}/house_expo_room_1451.json
         ${FLOORPLANS}/office_mlstruct_302.json ${FLOORPLANS}/office_mlstruct_848.json)

# Issue 49: a robot that cannot turn in place (--min-turn-radius): every arc certified, the
# floor still covered, the arcs in --json, far from the origin too; bad radii refused.
cli_test(cover_min_turn_radius_gallery 0 "drivable with turning radius 0\\.3: [0-9]+ arcs, every one certified" -
         cover ${EXAMPLES}/gallery.json --width 0.5 --radius 0.25 --angle 0 --min-turn-radius 0.3)
cli_test(cover_min_turn_radius_covers_the_floor 0 "covered 99\\.9[0-9]*% of the configuration space" -
         cover ${EXAMPLES}/gallery.json --width 0.5 --radius 0.25 --angle 0 --min-turn-radius 0.3)
add_test(NAME cli.cover_min_turn_radius_json COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "d['min_turn_radius'] == 0.3 and len(d['arcs']) > 50 and all(a['radius'] == 0.3 for a in d['arcs']) and 'turn' in d['moves'] and d['metrics']['covered_fraction'] > 0.995"
         -- $<TARGET_FILE:preimage_cli> cover ${EXAMPLES}/gallery.json --width 0.5 --radius 0.25 --angle 0 --min-turn-radius 0.3 --json)
# A turning radius larger than the gaps: the robot reverses where no forward curve fits.
cli_test(cover_min_turn_radius_reverses_where_needed 0 "drivable with turning radius 1: [0-9]+ arcs, every one certified. [1-9][0-9]* changes of direction" -
         cover ${EXAMPLES}/gallery.json --width 0.5 --radius 0.25 --angle 0 --min-turn-radius 1)
cli_test(cover_min_turn_radius_far_from_the_origin 0 "covered 99\\.9[0-9]*% of the configuration space \\(84\\.0420140764 m2\\)" -
         cover ${FIX}/scenes/room_with_hole_at_1e10.json --radius 0.25 --min-turn-radius 0.4)
cli_test(cover_min_turn_radius_too_large fail "--min-turn-radius 9: a U-turn needs 18 across, and the whole environment is 14\\.4222051019 across" -
         cover ${EXAMPLES}/gallery.json --width 0.5 --min-turn-radius 9)
cli_test(cover_min_turn_radius_negative fail "--min-turn-radius" - cover ${EXAMPLES}/gallery.json --width 0.5 --min-turn-radius -1)
cli_test(cover_min_turn_radius_not_online fail "--min-turn-radius: not with --online" -
         cover ${EXAMPLES}/gallery.json --radius 0.25 --online --min-turn-radius 0.5)
# Merged bends: a turn's worth in metres; negative refused, 0 keeps shortest transits.
cli_test(cover_turn_cost_negative fail "--turn-cost" - cover ${EXAMPLES}/gallery.json --width 0.5 --turn-cost -1)
# On the office floor (W = 0.5) most turns over 1 degree are chords of arcs: at 90 degrees
# with every cell on its own (one candidate, so only the bends differ), 1,303 turns hugging
# them, 966 with the default turn cost (docs/coverage.md).
add_test(NAME cli.cover_turn_cost_merges_bends COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "d['turns'] < 1100 and d['turns_over_15_deg'] <= 540 and d['metrics']['covered_fraction'] > 0.999"
         -- $<TARGET_FILE:preimage_cli> cover ${FLOORPLANS}/office_mlstruct_302.json --width 0.5 --radius 0.25 --angle 90 --no-merge --json)
# Cells merged into monotone regions: on the office floor at W = 0.3 the merged path is
# kept (2,218.9 m and 362 laps with every cell on its own before the order search's double
# bridges, docs/coverage.md); --no-merge keeps every cell on its own.
add_test(NAME cli.cover_merges_monotone_cells COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "d['merged_cells'] > 0 and d['laps'] < 362 and d['length'] < 2218 and d['metrics']['covered_fraction'] > 0.999"
         -- $<TARGET_FILE:preimage_cli> cover ${FLOORPLANS}/office_mlstruct_302.json --width 0.3 --radius 0.15 --json)
add_test(NAME cli.cover_no_merge COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "d['merged_cells'] == 0 and d['metrics']['covered_fraction'] > 0.999"
         -- $<TARGET_FILE:preimage_cli> cover ${FLOORPLANS}/office_mlstruct_302.json --width 0.3 --radius 0.15 --no-merge --json)
cli_test(cover_no_merge_only_boustrophedon fail "--no-merge: only the boustrophedon pattern merges cells" -
         cover ${EXAMPLES}/gallery.json --width 0.5 --pattern spiral --no-merge)
add_test(NAME cli.cover_turn_cost_zero_hugs_the_arcs COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/cli/json_expect.py
         "d['turns'] > 1250"
         -- $<TARGET_FILE:preimage_cli> cover ${FLOORPLANS}/office_mlstruct_302.json --width 0.5 --radius 0.25 --angle 90 --no-merge --turn-cost 0 --json)
