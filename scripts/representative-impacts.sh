#!/usr/bin/env bash
# The table of docs/swing-3d.md, "Representative impacts": the fastball and
# the knuckleball at Table II's fastball swing (the presets' E, ψ, 30 m/s,
# μ = 0.5), the swing plane tilted 30° (`bat.tilt=0.5236`), the bat's
# direction −20°, 0 and +20°, both hands, as Markdown:
#   scripts/representative-impacts.sh
# Angles in degrees (+ toward right field), spins in rpm.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
homerun=target/release/homerun
echo "| pitch | hand | φ_B | speed m/s | angle | direction | backspin | sidespin | gyro | range | lands at |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for pitch in fastball knuckleball; do
  for hand in right left; do
    if [ "$hand" = right ]; then directions="-20 0 20"; else directions="20 0 -20"; fi
    for degrees in $directions; do
      radians=$(awk -v d="$degrees" 'BEGIN { printf "%.6f", d * 3.141592653589793 / 180 }')
      "$homerun" hit --preset "$pitch" --json --set bat.tilt=0.5236 --set "bat.hand=$hand" \
        --set "bat.direction=$radians" |
        jq -r --arg pitch "$pitch" --arg hand "$hand" --arg degrees "$degrees" '
          def deg: . * 180 / 3.141592653589793;
          def rpm: . * 60 / (2 * 3.141592653589793);
          def f(n): (. * pow(10; n) | round) as $i
            | ($i | fabs | tostring) as $s
            | (n + 1 - ($s | length)) as $pad
            | (if $pad > 0 then "0" * $pad else "" end) + $s
            | (if n > 0 then .[0:length - n] + "." + .[length - n:] else . end)
            | if $i < 0 then "−" + . elif $i > 0 then "+" + . else . end;
          def u(n): f(n) | ltrimstr("+");
          ($degrees | tonumber) as $d
          | "| \($pitch) | \($hand[0:1] | ascii_upcase) | \(if $d == 0 then "0" else ($d | f(0)) + "°" end) "
          + "| \(.impact.launch_speed | u(2)) | \(.impact.launch_angle | deg | u(1))° | \(.impact.launch_direction | deg | f(1))° "
          + "| \(.impact.launch_spin | rpm | u(0)) | \(.impact.launch_sidespin | rpm | f(0)) | \(.impact.launch_gyrospin | rpm | f(0)) "
          + "| \(.flight.range | u(1)) m | \(.flight.direction | deg | f(1))° |"'
    done
  done
done
