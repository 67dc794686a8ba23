# The golden cases, one add_golden_test() a case. Refresh: scripts/refresh-goldens.sh
