#!/usr/bin/env bash
# The paper's scene stepping on an emulated Cortex-M4F (QEMU's mps2-an386), in CI, in f32 (the
# FPU's precision) and in f64 (computed in software) for comparison:
# - its end state after 2 000 RK4 steps of 1 ms against the host's f64 run of the same loop
#   (`firmware_reference`, the first argument): in f64 q and λ within 1e-9 relative and
#   |g| ≤ 1e-10; in f32 q within 1e-4, λ within 1e-3 and |g| ≤ 1e-5;
# - instructions per step, counted from QEMU's single-step trace of two builds that differ
#   only in the number of steps (QEMU models no cycle counter);
# - the stack's high-water mark (painted stack) and the ELF's code size.
set -euo pipefail
host_reference=$(realpath "$1")
cd "$(dirname "$0")"
elf=target/thumbv7em-none-eabihf/release/zeitner-on-target
qemu=(qemu-system-arm -M mps2-an386 -cpu cortex-m4 -nographic
  -semihosting-config enable=on,target=native)
on_host=$("$host_reference" 2000)
echo "host (f64): $on_host"

# check <scalar> <q bound> <λ bound> <|g| bound>: runs the firmware and compares its end state.
check() {
  "${qemu[@]}" -kernel "$elf" > "target/on-target-$1.log"
  grep "^t " "target/on-target-$1.log" | tail -n 2
  local on_target
  on_target=$(tail -n 1 "target/on-target-$1.log")
  echo "target ($1): $on_target"
  python3 - "$on_target" "$on_host" "$@" <<'PY'
import sys
def fields(line):
    words = line.split()
    return {words[i]: [float(x) for x in words[i + 1:i + 4] if not x.isalpha()]
            for i, w in enumerate(words) if w.isalpha()}
target, host = fields(sys.argv[1]), fields(sys.argv[2])
scalar, q_bound, lambda_bound, g_bound = sys.argv[3], *map(float, sys.argv[4:7])
def worst(key):
    return max(abs(a - b) / max(abs(b), 1e-300) for a, b in zip(target[key], host[key]))
q, lam, g = worst("q"), worst("lambda"), max(abs(x) for x in target["g"])
print(f"{scalar} accuracy after 2 s against the host's f64: q {q:.1e}, λ {lam:.1e} relative; |g| {g:.1e}")
stepping, whole = target["stack"][:2]
print(f"{scalar} stack high-water mark: {stepping:.0f} bytes for the start and the steps "
      f"({whole:.0f} with the reports' formatting)")
assert q <= q_bound and lam <= lambda_bound and g <= g_bound, "the target's run is off the host's"
PY
}

count() {
  ZEITNER_TARGET_STEPS=$1 cargo build --release --quiet "${@:2}"
  "${qemu[@]}" -singlestep -d exec,nochain -D "target/trace-$1.log" -kernel "$elf" > /dev/null
  grep -c '^Trace' "target/trace-$1.log"
}

for scalar in f32 f64; do
  features=()
  test "$scalar" = f32 && features=(--features f32)
  few=$(count 5 "${features[@]}")
  more=$(count 10 "${features[@]}")
  rm -f target/trace-*.log
  echo "$scalar instructions per step: $(( (more - few) / 5 )) (traces of 5 and 10 steps: $few, $more)"
  cargo build --release --quiet "${features[@]}"
  if test "$scalar" = f32; then check f32 1e-4 1e-3 1e-5; else check f64 1e-9 1e-9 1e-10; fi
  size -A "$elf" | awk -v s="$scalar" '$1 == ".text" {print s " .text of the firmware (with semihosting and float printing): " $2 " bytes"}'
done
