#!/usr/bin/env bash
# The main job: set up, build, and print the reference table of the study's exact values.
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/build.sh build
./build/contact-suite oracle table
