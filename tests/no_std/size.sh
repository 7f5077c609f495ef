#!/usr/bin/env bash
# Code size of the no_std stepping loop over the steam generator for thumbv7em-none-eabihf
# (opt-level "s", LTO): the .text of the crate's own object, which holds the scene's generated
# code, the runtime and the libm functions it calls (compiler_builtins, linked as needed, apart).
# `size`'s "text" column: `.text` with the read-only data (the tableaux, libm's tables).
set -euo pipefail
cd "$(dirname "$0")"
target=thumbv7em-none-eabihf
echo "| runtime features | sensitivity | .text (bytes) |"
echo "|---|---|---|"
while IFS='|' read -r features label sensitivity; do
  cargo build --quiet --release --target "$target" ${features:+--features "$features"}
  bytes=$(size "target/$target/release/libzeitner_no_std_check.a" | awk '/zeitner_no_std_check.*rcgu/ {s += $1} END {print s}')
  echo "| $label | $sensitivity | $bytes |"
done <<'PLAN'
|none (minimal)|paper
f32|f32 (minimal)|paper
exact|exact-sensitivity|exact
full|exact-sensitivity, implicit, high-order, dense-output (the defaults but std)|exact
PLAN
