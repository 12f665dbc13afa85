#!/usr/bin/env bash
# Runs the libFuzzer targets one after another: usage run_fuzz.sh FUZZ_BUILD SECONDS [TARGET...]
# (targets without the fuzz_ prefix; default: every bin/fuzz_* but fuzz_seeds). Each target reads
# FUZZ_BUILD/seeds/T (make_seeds.sh) and grows FUZZ_BUILD/corpus/T; findings (crash, leak,
# timeout, out-of-memory, broken invariant) land in FUZZ_BUILD/artifacts/ as T-crash-..., its
# log in FUZZ_BUILD/logs/T.log. One process per target (-jobs is not used: the machine is shared).
# Prints one line per target: executions, rate, coverage (cov = edges, ft = features), corpus
# size, peak RSS and findings; exits 1 when any target had a finding.
# Environment: FUZZ_MAX_LEN (bytes, default 4096; slr_oc gets twice that), FUZZ_RSS_MB (2048),
# FUZZ_TIMEOUT (s per input, 10), FUZZ_ARGS (more libFuzzer flags).
set -uo pipefail
build=${1:?fuzz build folder}; seconds=${2:?seconds per target}; shift 2
maxlen=${FUZZ_MAX_LEN:-4096}
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for exe in "$build"/bin/fuzz_*; do
    t=${exe##*/fuzz_}
    [ "$t" = seeds ] || targets+=("$t")
  done
fi
mkdir -p "$build/artifacts" "$build/logs"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
failed=()
printf '%-20s %12s %9s %7s %7s %7s %8s  %s\n' target executions exec/s cov ft corpus rss_mb findings
for t in "${targets[@]}"; do
  exe="$build/bin/fuzz_$t"
  if [ ! -x "$exe" ]; then echo "run_fuzz: $exe not built" >&2; failed+=("$t"); continue; fi
  mkdir -p "$build/corpus/$t" "$build/seeds/$t"
  len=$maxlen; [ "$t" = slr_oc ] && len=$((2 * maxlen))
  log="$build/logs/$t.log"
  before=$(ls "$build/artifacts" | grep -c "^$t-" || true)
  # shellcheck disable=SC2086
  "$exe" "$build/corpus/$t" "$build/seeds/$t" -max_total_time="$seconds" -max_len="$len" \
    -timeout="${FUZZ_TIMEOUT:-10}" -rss_limit_mb="${FUZZ_RSS_MB:-2048}" -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/$t-" ${FUZZ_ARGS:-} > "$log" 2>&1
  rc=$?
  after=$(ls "$build/artifacts" | grep -c "^$t-" || true)
  stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -1; }
  last=$(grep -E '^#[0-9]+' "$log" | grep ' cov: ' | tail -1)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last"); ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\).*/\1/p' <<<"$last")
  findings=$((after - before))
  what="$findings"
  if [ $rc -ne 0 ] || [ $findings -gt 0 ]; then
    failed+=("$t")
    kind=$(grep -m1 -oE 'ERROR: [A-Za-z]+: [^ ]+( [^ ]+)?|runtime error: .*|out-of-memory|timeout after' "$log" | head -c 90)
    where=$(grep -m1 -oE '(core|ui|tests/fuzz)/[a-z_/]+\.(cpp|hpp):[0-9]+' "$log")  # a trap: the broken check
    what="$findings ($kind${where:+ at $where}; see $log)"
  fi
  printf '%-20s %12s %9s %7s %7s %7s %8s  %s\n' "$t" "$(stat number_of_executed_units)" \
    "$(stat average_exec_per_sec)" "${cov:--}" "${ft:--}" "${corp:--}" "$(stat peak_rss_mb)" "$what"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "run_fuzz: findings or failures in: ${failed[*]} (inputs in $build/artifacts/)" >&2
  exit 1
fi
