#!/usr/bin/env bash
# The table of docs/swing-3d.md, "The best swing for a park": `optimize
# --park` at a few parks for a right- and a left-handed batter (the
# fastball's swing, the barrel 30° below the hands), as Markdown:
#   scripts/park-optima.sh
# Angles in degrees (+ toward right field), lengths in metres.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
homerun=target/release/homerun
echo "| park | batter | E | ψ | φ_B | launch | crosses the fence | wall there | margin | over the wall | inside the line |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for park in LAD NYY BOS HOU SF COL; do
  for hand in right left; do
    "$homerun" optimize --json --park "$park" --set bat.tilt=0.5236 --set "bat.hand=$hand" |
      jq -r --arg hand "$hand" '
        def deg: . * 180 / 3.141592653589793;
        def f(n): (. * pow(10; n) | round) as $i
          | ($i | fabs | tostring) as $s
          | (n + 1 - ($s | length)) as $pad
          | (if $pad > 0 then "0" * $pad else "" end) + $s
          | .[0:length - n] + "." + .[length - n:]
          | if $i < 0 then "−" + . else . end;
        "| \(.park) | \($hand) | \(.undercut * 1000 | f(1)) mm | \(.swing_angle | deg | f(1))° | \(.bat_direction | deg | f(1))° "
        + "| \(.launch_speed | f(1)) m/s, \(.launch_angle | deg | f(1))°, \(.direction | deg | f(1))° "
        + "| \(.fence.direction | deg | f(1))°, \(.fence.height_at_fence | f(1)) m up | \(.fence.distance | f(1)) m, \(.fence.height | f(1)) m high "
        + "| **\(.margin | f(2)) m** | \(.over_wall | f(2)) m | \(.inside_line | f(2)) m |"'
  done
done
