# The golden cases, one add_golden_test() a case. Refresh: scripts/refresh-goldens.sh
add_golden_test(show_lab4x4 ARGS show worlds/lab4x4.txt)
add_golden_test(show_lab4x4_xml ARGS show worlds/lab4x4.xml)
add_golden_test(generate_8x8_seed1 ARGS generate 8x8 --seed 1)
add_golden_test(error_inconsistent_num STATUS 2 ARGS show tests/data/worlds/inconsistent.num)
