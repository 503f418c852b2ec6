#!/usr/bin/env bash
# Regenerates the pictures of the README and docs/ from the release build:
#   scripts/pictures.sh
# Each is what the command line writes with --svg; the bench diagram is the
# quick bench on this machine (its times vary with the machine and its load).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
homerun=target/release/homerun
"$homerun" trajectory --samples 201 --svg docs/trajectory.svg
"$homerun" trajectory --samples 201 --preset fly-ball --set launch.direction=-0.349066 --set launch.sidespin=-104.72 --set environment.wind=4.4704 --set environment.wind_direction=1.570796 --svg docs/trajectory-3d.svg
"$homerun" surface --grid 61x49 --svg docs/surface.svg
"$homerun" figure 8 --svg docs/figure8.svg
"$homerun" figure 13 --svg docs/figure13.svg
"$homerun" figure 14 --svg docs/figure14.svg
"$homerun" bench --quick --svg docs/work-precision.svg
