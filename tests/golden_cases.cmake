# The golden cases, one add_golden_test() a case. Refresh: scripts/refresh-goldens.sh

# The 1-D log-odds exercise and the model's numbers (issue 2); no arguments maps the default world.
add_golden_test(main_no_arguments)
add_golden_test(demo_1d_default ARGS demo 1d)
add_golden_test(demo_1d_log_base_10 ARGS demo 1d --log-base 10)
add_golden_test(demo_1d_shuffle ARGS demo 1d --order shuffle --seed 7)
add_golden_test(explain_default ARGS explain)
add_golden_test(explain_clamp ARGS explain --clamp -2 3.5)
add_golden_test(demo_1d_bad_resolution STATUS 2 STDERR ARGS demo 1d --resolution 0)
add_golden_test(demo_1d_bad_measurement STATUS 2 STDERR ARGS demo 1d --measurements "101, 82,abc")
add_golden_test(demo_1d_svg_unwritable STATUS 2 STDERR ARGS demo 1d --svg /nonexistent-dir/plot.svg)
add_golden_test(show_lab4x4 ARGS show worlds/lab4x4.txt)
add_golden_test(show_lab4x4_xml ARGS show worlds/lab4x4.xml)
add_golden_test(generate_8x8_seed1 ARGS generate 8x8 --seed 1)
add_golden_test(error_inconsistent_num STATUS 2 STDERR ARGS show tests/data/worlds/inconsistent.num)

# The main job (issue 5): maze runs, byte for byte.
add_golden_test(run_lab4x4_k3_cell_noise_off ARGS run worlds/lab4x4.txt --noise 0)
add_golden_test(run_lab4x4_k5_cell ARGS run worlds/lab4x4.txt --subcells 5)
add_golden_test(run_lab4x4_k3_ray ARGS run worlds/lab4x4.txt --model ray)
add_golden_test(run_lab4x4_k5_ray_noise_off ARGS run worlds/lab4x4.txt --model ray --subcells 5 --noise 0)
add_golden_test(run_lab4x4_seed7_noisy ARGS run worlds/lab4x4.txt --model ray --noise 0.01 --seed 7)
add_golden_test(run_lab4x4_ascii_unknown ARGS run worlds/lab4x4.txt --ascii --unknown . --quiet)
add_golden_test(run_classic16_quiet ARGS run worlds/classic16x16.txt --quiet)
add_golden_test(run_maze8_frontier_quiet ARGS run worlds/maze8x8.txt --strategy frontier --quiet)
add_golden_test(run_bad_p_occ STATUS 2 STDERR ARGS run --p-occ 0.4)
add_golden_test(run_bad_subcells STATUS 2 STDERR ARGS run --subcells 4)
add_golden_test(run_unknown_strategy STATUS 2 STDERR ARGS run --strategy spiral)
