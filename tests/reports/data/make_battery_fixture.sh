#!/usr/bin/env bash
# Writes tests/reports/data/battery_results.json: a real run of contact-suite on the study's
# C, M, F meshes (patch tests, Hertz, a Steuermann punch, the flat punch; Q4 and Q8; all five
# algorithms; ss and ns), with the surface profiles dropped to keep the file small. The verdict
# page, claims ledger and gold-report tests read it. Regenerate after a change that moves results:
#   bash tests/reports/data/make_battery_fixture.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/../../.."
exe=${1:-build}/contact-suite
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" run --problems P_p,Pprime_p,H_p,S_1,F_p --elements Q4,Q8 --contacts ss,ns \
  --recovery spr,extrapolated --no-report --out "$tmp/run" || [ $? -le 1 ]
python3 - "$tmp/run/results.json" tests/reports/data/battery_results.json <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
for case in doc["cases"]:
    case.pop("profile", None)
    case.pop("exact_profile", None)
doc["run"]["command_line"] = "contact-suite run (tests/reports/data/make_battery_fixture.sh)"
doc["run"]["environment"] = {"machine": "fixture"}
json.dump(doc, open(sys.argv[2], "w"), separators=(",", ":"), sort_keys=True)
PY
echo "wrote tests/reports/data/battery_results.json"
