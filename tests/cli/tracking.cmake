# End-to-end tests of the command line: tracking. Included from tests/CMakeLists.txt,
# which defines cli_test(), EXPECT, FIX, EXAMPLES, FLOORPLANS and OUT.
set(TRACKING ${EXAMPLES}/tracking)
cli_test(track_ept 0 "^SDE\\(q\\^t, q\\^o\\) = [0-9.]+ through edge [0-9]+$" - track ept ${TRACKING}/chair.json --svg ${OUT}/ept.svg)
cli_test(track_ept_point 0 "^escape-path tree: [0-9]+ nodes" - track ept ${TRACKING}/lab.json --observer 2,6 --target 5,5.5)
cli_test(track_ept_json 0 "\"exit\":\"(corner|perpendicular)\"" - track ept ${TRACKING}/box.json --json)
cli_test(track_ept_target_hidden fail "--target 5,10: not strictly inside the observer's visibility polygon" - track ept ${TRACKING}/lab.json --observer 2,6 --target 5,10)
cli_test(track_ept_solid_edge_seen_edge_on 0 "^escape-path tree: [0-9]+ nodes" - track ept ${FIX}/scenes/lab_solid_edge_seen_edge_on.json)
cli_test(track_ept_observer_in_line_with_vertices fail "observer at \\(3, 7.8\\): its visibility polygon, rounded to doubles, is not star-shaped" - track ept ${FIX}/scenes/lab_observer_in_line_with_vertices.json)
cli_test(track_ept_observer_in_obstacle fail "--observer 4.1,4.1: not in the open free space" - track ept ${TRACKING}/lab.json --observer 4.1,4.1 --target 2,6)
cli_test(track_simulate 0 "^escape time: never \\(kept in sight\\)$" - track simulate ${TRACKING}/corridor.json --svg ${OUT}/run.svg)
cli_test(track_simulate_adversarial 0 "^visible: [0-9.]+% of the time$" - track simulate ${TRACKING}/box.json --target-policy adversarial --strategy sde --steps 50)
cli_test(track_simulate_cone 0 "^path length: observer" - track simulate ${TRACKING}/lab.json --fov 180 --target-policy random --seed 4 --steps 100)
cli_test(track_simulate_bad_policy fail "--target-policy: expected scripted, random, adversarial, lookahead or game, got \"x\"" - track simulate ${TRACKING}/box.json --target-policy x)
cli_test(track_simulate_lookahead 0 "^escape time: " - track simulate ${TRACKING}/box.json --target-policy lookahead --steps 40 --headings 8 --lookahead-steps 3)
cli_test(track_simulate_dynamics 0 "^command variation: [0-9.]+ m/s and [0-9.]+ rad/s per second$" - track simulate ${TRACKING}/lab.json --target-policy random --accel 0.5 --alpha 1.5 --steps 60)
cli_test(track_simulate_log 0 "^escape time: " ${OUT}/box-steps.jsonl track simulate ${TRACKING}/box.json --target-policy adversarial --steps 30 --log ${OUT}/box-steps.jsonl)
cli_test(track_simulate_json_commands 0 "\"command_variation\":\\{" - track simulate ${TRACKING}/box.json --steps 10 --json)
cli_test(track_simulate_negative_steps fail "--steps: expected an integer from 1 to 1000000, got -1" - track simulate ${TRACKING}/box.json --steps -1)
cli_test(track_simulate_too_many_steps fail "--steps: expected an integer from 1 to 1000000, got 1000001" - track simulate ${TRACKING}/box.json --steps 1000001)
cli_test(track_simulate_negative_seed fail "--seed: expected an integer from 0 to 9223372036854775807, got -3" - track simulate ${TRACKING}/box.json --seed -3)
cli_test(track_simulate_bad_fov fail "--fov: expected 180 or 360, got '90'" - track simulate ${TRACKING}/box.json --fov 90)
cli_test(track_simulate_bad_accel fail "--accel: expected a number in \\(0, 100\\], got -1" - track simulate ${TRACKING}/box.json --accel -1)
cli_test(track_simulate_bad_alpha fail "--alpha: expected a number in \\(0, 1000\\], got 'nan'" - track simulate ${TRACKING}/box.json --alpha nan)
cli_test(track_simulate_bad_headings fail "--headings: expected an integer from 1 to 360, got 0" - track simulate ${TRACKING}/box.json --headings 0)
cli_test(track_simulate_bad_lookahead fail "--lookahead-steps: expected an integer from 1 to 50, got 51" - track simulate ${TRACKING}/box.json --lookahead-steps 51)
cli_test(track_simulate_bad_speed_ratio fail "--speed-ratio: expected a number in \\(0, 10\\], got 0" - track simulate ${TRACKING}/box.json --speed-ratio 0)
cli_test(track_simulate_bad_start_spread fail "--start-spread: expected a number in \\[0, 100\\], got -1" - track simulate ${TRACKING}/box.json --start-spread -1)
cli_test(track_evaluate_bad_heading_spread fail "--heading-spread: expected a number in \\[0, 180\\], got 200" - track evaluate ${TRACKING}/box.json --heading-spread 200)
cli_test(track_ept_huge_m fail "--m: expected an integer from 0 to 16, got 2147483647" - track ept ${TRACKING}/box.json --m 2147483647)
cli_test(track_ept_negative_m fail "--m: expected an integer from 0 to 16, got -1" - track ept ${TRACKING}/box.json --m -1)
cli_test(track_ept_bad_radius fail "--radius: expected a number in \\(0, 100\\], got -0.2" - track ept ${TRACKING}/box.json --radius -0.2)
cli_test(track_simulate_no_slot fail "the scene has no \"tracking\" slot" - track simulate ${EXAMPLES}/gallery.json)
cli_test(track_evaluate 0 "^\\| cardboard box \\(Fig. 6b\\) \\| 180° \\| yes \\| lookahead \\| [0-2]/2 \\(with dynamics\\) \\| [0-2]/[0-2] \\| [0-2]/2, " - track evaluate ${TRACKING}/box.json --seeds 2 --steps 20 --game-resolution 0.5 --headings 4 --lookahead-steps 2)
cli_test(track_evaluate_json 0 "\"minus_sde\":\\{" - track evaluate ${TRACKING}/box.json --seeds 2 --steps 20 --game-resolution 0.5 --fov 360 --dynamics off --target-policy adversarial --json)
cli_test(track_evaluate_cdf 0 "^\\| cardboard box" ${OUT}/cdf.svg track evaluate ${TRACKING}/box.json --seeds 2 --steps 20 --game-resolution 0.5 --fov 180 --dynamics on --target-policy random,adversarial --strategy risk,sde --cdf-svg ${OUT}/cdf.svg)
# With dynamics the starts are judged with the observer's velocity in the state; 0 turns that off.
cli_test(track_evaluate_dynamic_game_json 0 "\"observer_dynamics\":true,\"resolution\":0.5,\"winnable\":\\[0,0\\]" -
         track evaluate ${TRACKING}/box.json --seeds 2 --steps 20 --game-resolution 0.5 --fov 360 --dynamics on --target-policy adversarial --strategy risk --json)
cli_test(track_evaluate_dynamic_game_off 0 "^\\| cardboard box \\(Fig. 6b\\) \\| 360° \\| yes \\| adversarial \\| [0-2]/2 \\| " -
         track evaluate ${TRACKING}/box.json --seeds 2 --steps 20 --game-resolution 0.5 --dynamic-game-resolution 0 --fov 360 --dynamics on --target-policy adversarial --strategy risk)
cli_test(track_evaluate_zero_seeds fail "--seeds: expected an integer from 1 to 10000, got 0" - track evaluate ${TRACKING}/box.json --seeds 0)
cli_test(track_evaluate_too_many_seeds fail "--seeds: expected an integer from 1 to 10000, got 10001" - track evaluate ${TRACKING}/box.json --seeds 10001)
cli_test(track_evaluate_negative_steps fail "--steps: expected an integer from 1 to 1000000, got -5" - track evaluate ${TRACKING}/box.json --steps -5)
cli_test(track_evaluate_bad_fov fail "--fov: expected 180 or 360, got '90'" - track evaluate ${TRACKING}/box.json --fov 360,90)
cli_test(track_evaluate_bad_dynamics fail "--dynamics: " - track evaluate ${TRACKING}/box.json --dynamics maybe)
cli_test(track_evaluate_bad_jobs fail "--jobs: expected an integer from 1 to 256, got 0" - track evaluate ${TRACKING}/box.json --jobs 0)
cli_test(track_evaluate_bad_strategy fail "--strategy: expected risk, sde, naive, game or risk-game, got \"x\"" - track evaluate ${TRACKING}/box.json --strategy risk,x)
cli_test(track_replay_fixture 0 "^1 scan replayed" - track replay ${FIX}/scans/aces_scan49_target_on_radial_edge.log)
cli_test(track_replay_svg_of_chosen_scans 0 "^6 scans replayed" ${OUT}/replay_scans.svg
         track replay ${EXAMPLES}/tracking/corridor_scans.txt --scans 0-3,5,4 --svg ${OUT}/replay_scans.svg)
cli_test(track_replay_json_has_geometry 0 "\"geometry\":\\{\"V\":\\[\\{\"from\":\\[.*\"escape_path_tree\":\\[\\{\"edge\":.*\"points\":\\[\\[.*\"scan\":3," -
         track replay ${EXAMPLES}/tracking/corridor_scans.txt --scans 3 --json)
cli_test(track_replay_scans_reversed_range fail "--scans: item '5-2' \\(character 3\\): expected a scan index N or a range A-B" -
         track replay ${EXAMPLES}/tracking/corridor_scans.txt --scans 1,5-2)
cli_test(track_replay_scans_beyond_log fail "--scans 500: the log has 12 scans \\(numbered from 0\\)" -
         track replay ${EXAMPLES}/tracking/corridor_scans.txt --scans 500)
cli_test(track_replay_svg_too_many_scans fail "--svg draws at most 24 scans. choose them with --scans" -
         track replay ${EXAMPLES}/tracking/corridor_scans.txt --scans 0-9,20-40 --svg ${OUT}/never.svg)
cli_test(track_replay_truncated_gz fail "aces_three_scans_truncated.log.gz: the file is truncated \\(its compressed stream ends early, in line 3\\)" - track replay ${FIX}/scans/aces_three_scans_truncated.log.gz)
cli_test(track_replay_bad_radius fail "--radius: expected a number in \\(0, 100\\], got 0" - track replay ${FIX}/scans/bad.log --radius 0)
cli_test(track_replay_bad_max_range fail "--max-range: expected a number in \\(0, 10000\\], got 'inf'" - track replay ${FIX}/scans/bad.log --max-range inf)
cli_test(track_replay_bad_ahead fail "--ahead: expected a number in \\(0, 10000\\], got -1" - track replay ${FIX}/scans/bad.log --ahead -1)
# a fuzzer's scan: beams 1.6e-47 rad apart (all one direction in double)
cli_test(track_replay_tiny_angle_increment fail "tiny_angle_increment\\.log:1: angle_increment 1\\.63971058433e-47 with angle_min -1\\.5707963 does not give beams distinct directions" - track replay ${FIX}/scans/tiny_angle_increment.log)
cli_test(track_replay_bad_token fail "bad.log:3: token 5 \\(\"x\"\\): expected a number" - track replay ${FIX}/scans/bad.log)
if(EXISTS ${PROJECT_SOURCE_DIR}/../shared/data/carmen/aces-corrected.log.gz)
  cli_test(track_replay_aces 0 "^440 scans replayed" - track replay ${PROJECT_SOURCE_DIR}/../shared/data/carmen/aces-corrected.log.gz)
endif()
# A huge legal run goes on, with progress on a terminal's stderr, until interrupted (SIGINT
# after 2.5 s: timeout's 124 says it was still running).
add_test(NAME cli.track_simulate_huge_steps_progress_interrupted
  COMMAND bash -c "cmd=\"timeout -s INT 2.5 $0 track simulate $1 --steps 1000000\"; out=$(script -qec \"$cmd\" /dev/null); rc=$?; echo \"$out\"; [ $rc -eq 124 ] && grep -Eq 'simulate: [0-9]+ of 1000000' <<<\"$out\""
          $<TARGET_FILE:preimage_cli> ${TRACKING}/corridor.json)
add_test(NAME cli.track_evaluate_huge_seeds_progress_interrupted
  COMMAND bash -c "cmd=\"timeout -s INT 2.5 $0 track evaluate $1 --seeds 10000 --game-resolution 0.5\"; out=$(script -qec \"$cmd\" /dev/null); rc=$?; echo \"$out\"; [ $rc -eq 124 ] && grep -Eq 'evaluate: [0-9]+ of 480000' <<<\"$out\""
          $<TARGET_FILE:preimage_cli> ${TRACKING}/box.json)

# The visibility game (ground truth): the box start is kept at 0.25 m, the chairs' start is not (at 0.2 m and finer).
cli_test(track_game_box 0 "^start, on the grid: observer \\(1, 3\\), target \\(5.25, 3\\): the observer keeps the target forever$" ${OUT}/game-box.svg track game ${TRACKING}/box.json --svg ${OUT}/game-box.svg)
cli_test(track_game_chairs 0 "the target escapes within 12 steps \\(6.79 s\\) against every observer" - track game ${TRACKING}/chair.json --resolution 0.2)
cli_test(track_game_point_target 0 "separation 0.35 m, target radius 0.00 m" - track game ${TRACKING}/box.json --resolution 0.5 --target-radius 0)
cli_test(track_game_json 0 "\"keeping_observers\":\\[" - track game ${TRACKING}/lab.json --resolution 0.5 --json)
# The game with the observer's velocity in the state (0.5 m/s^2 per axis, at rest at the
# start): the box's start is still kept; the chairs' start, kept without dynamics at this
# grid, is lost within 11 steps.
cli_test(track_game_box_dynamics 0 "^start with dynamics: the observer, starting at rest, keeps the target forever$" - track game ${TRACKING}/box.json --accel 0.5)
cli_test(track_game_chairs_dynamics 0 "^start with dynamics: the target escapes within 11 steps \\(7.78 s\\) against every observer starting at rest$" -
         track game ${TRACKING}/chair.json --accel 0.5)
cli_test(track_game_dynamics_json 0 "\"dynamics\":\\{\"accel\":0.5,\"accel_steps\":2," - track game ${TRACKING}/box.json --resolution 0.5 --accel 0.5 --json)
cli_test(track_game_dynamics_off_grid fail "the velocities carry grid points to grid points only at a multiple of 0.25 m" -
         track game ${TRACKING}/box.json --resolution 0.125 --accel 0.5)
# The robot's own motion (constant acceleration for a step, sqrt(2 h / accel) long): the
# box's start is still kept at 0.25 m; the lab's is lost at 0.5 m (every lab state is).
cli_test(track_game_box_constant_acceleration 0
         "constant-acceleration steps of 1.00 s, 13 velocities\\): 25992148 states .* from 9892448 of the 16474406 states" -
         track game ${TRACKING}/box.json --accel 0.5 --observer-step constant-acceleration)
cli_test(track_game_lab_constant_acceleration 0
         "^start with dynamics: the target escapes within 10 steps \\(14.14 s\\) against every observer starting at rest$" -
         track game ${TRACKING}/lab.json --resolution 0.5 --accel 0.5 --observer-step constant-acceleration)
cli_test(track_game_constant_acceleration_too_short fail "the target moves at most 0.05.* m, less than one grid step" -
         track game ${TRACKING}/box.json --accel 50 --observer-step constant-acceleration)
cli_test(track_game_bad_observer_step fail "--observer-step: .*euler" - track game ${TRACKING}/box.json --accel 0.5 --observer-step euler)
cli_test(track_game_zero_resolution fail "--resolution: expected a number in" - track game ${TRACKING}/box.json --resolution 0)
cli_test(track_game_huge_grid fail "game: .* states, more than the limit" - track game ${TRACKING}/box.json --resolution 0.01)
cli_test(track_game_target_outside fail "--target \\(50, 50\\): no grid point of the game within two grid steps" - track game ${TRACKING}/box.json --target 50,50)
cli_test(track_simulate_game 0 "^escape time: " - track simulate ${TRACKING}/box.json --strategy game --target-policy game --steps 40 --game-resolution 0.5)
cli_test(track_simulate_risk_game 0 "^escape time: " - track simulate ${TRACKING}/lab.json --strategy risk-game --target-policy adversarial --steps 40 --game-resolution 0.5)
cli_test(track_evaluate_game 0 "\"kept_winnable_fraction\":\\{" - track evaluate ${TRACKING}/box.json --seeds 2 --steps 20 --fov 360 --dynamics off --target-policy adversarial,game --strategy risk,game,risk-game --game-resolution 0.5 --json)
cli_test(track_evaluate_game_off fail "the game strategies and the game target need the game" - track evaluate ${TRACKING}/box.json --seeds 1 --steps 5 --strategy game --game-resolution 0)
