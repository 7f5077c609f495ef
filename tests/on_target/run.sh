#!/usr/bin/env bash
# The paper's scene stepping on an emulated Cortex-M4F (QEMU's mps2-an386), in CI:
# - its end state after 2 000 RK4 steps of 1 ms against the host's run of the same loop
#   (`firmware_reference`, the first argument), q and λ within 1e-9 relative, |g| ≤ 1e-10;
# - instructions per step, counted from QEMU's single-step trace of two builds that differ
#   only in the number of steps (QEMU models no cycle counter);
# - the stack's high-water mark (painted stack) and the ELF's code size.
set -euo pipefail
host_reference=$(realpath "$1")
cd "$(dirname "$0")"
elf=target/thumbv7em-none-eabihf/release/zeitner-on-target
qemu=(qemu-system-arm -M mps2-an386 -cpu cortex-m4 -nographic
  -semihosting-config enable=on,target=native)

cargo build --release --quiet
"${qemu[@]}" -kernel "$elf" > target/on-target.log
grep "^t " target/on-target.log
on_target=$(tail -n 1 target/on-target.log)
on_host=$("$host_reference" 2000)
echo "target: $on_target"
echo "host:   $on_host"
python3 - "$on_target" "$on_host" <<'PY'
import sys
def fields(line):
    words = line.split()
    return {words[i]: [float(x) for x in words[i + 1:i + 4] if not x.isalpha()]
            for i, w in enumerate(words) if w.isalpha()}
target, host = fields(sys.argv[1]), fields(sys.argv[2])
worst = 0.0
for key in ("q", "lambda"):
    for a, b in zip(target[key], host[key]):
        worst = max(worst, abs(a - b) / max(abs(b), 1e-300))
g = max(abs(x) for x in target["g"])
print(f"q and λ on the target against the host: {worst:.1e} relative; |g| {g:.1e}")
assert worst <= 1e-9 and g <= 1e-10, "the target's run differs from the host's"
PY

count() {
  ZEITNER_TARGET_STEPS=$1 cargo build --release --quiet
  "${qemu[@]}" -singlestep -d exec,nochain -D "target/trace-$1.log" -kernel "$elf" > /dev/null
  grep -c '^Trace' "target/trace-$1.log"
}
few=$(count 5)
more=$(count 10)
rm -f target/trace-*.log
echo "instructions per RK4 step: $(( (more - few) / 5 )) (traces of 5 and 10 steps: $few, $more)"
cargo build --release --quiet
echo "stack high-water mark: $(echo "$on_target" | awk '{print $NF}') bytes"
size -A "$elf" | awk '$1 == ".text" {print ".text of the ELF (with semihosting and float printing): " $2 " bytes"}'
