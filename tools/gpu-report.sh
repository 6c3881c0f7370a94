#!/usr/bin/env bash
# A real GPU's report in one command, for the few minutes a GPU is lent: builds
# glyphscope if needed, checks that the adapter is not a CPU implementation (one line
# on stderr and exit 2 if it is: lavapipe's or SwiftShader's figures are not a GPU's),
# then runs `render --stats` of every method on the standard page, a motion drift,
# the quick bench with the peers and, where GPU_REPORT_BUDGET_S leaves time, the full
# bench, and writes them with a README (adapter, driver, date,
# each command and its wall time) to docs/bench/gpu/<adapter>/. Progress on stdout.
#   bash tools/gpu-report.sh
# WGPU_ADAPTER_NAME chooses the adapter (a part of its name); GLYPHSCOPE_BIN names a
# built binary to use instead of building. The build tries cargo's --offline first (a
# machine without network, the registry already in cargo's cache), then online.
# docs/bench.md ("A real GPU in one command") says what it runs and how long it takes.
set -euo pipefail
# The C locale: EPOCHREALTIME's decimal point, and tr and sed on plain ASCII.
export LC_ALL=C
cd "$(dirname "$0")/.."
# shellcheck source=tools/methods.sh
. tools/methods.sh
# Milliseconds since the epoch, and those since `$1` as seconds to a tenth.
now_ms() { local t=${EPOCHREALTIME/./}; echo $((t / 1000)); }
since() { local d=$(($(now_ms) - $1)); echo "$((d / 1000)).$((d % 1000 / 100)) s"; }
started=$(now_ms)

# The quick bench's scenes (see docs/bench.md for why these): every standard scene and
# the scaling series.
bench_args=(bench --quick)
# The motion drift: the page drifting 1/16 px a frame along x, every GPU method and peer,
# as docs/motion.md's table runs it.
motion_args=(motion --case page --path "drift:0.0625,0" --frames 32
    --method "winding,sdf-cells,xor-stencil,tessellation,atlas,vello,glyphon,vello-cpu"
    --animate "atlas,winding")

say() { echo "[gpu-report $(date -u +%H:%M:%S), $(since "$started")] $*"; }

fail() {
    echo "error: $*" >&2
    exit 2
}

if [ -n "${GLYPHSCOPE_BIN:-}" ]; then
    bin=$GLYPHSCOPE_BIN
    [ -x "$bin" ] || fail "GLYPHSCOPE_BIN=$bin is not an executable file"
    build_line="(none: the binary given by GLYPHSCOPE_BIN, $bin)"
    build_time="0 s"
else
    command -v cargo >/dev/null \
        || fail "building glyphscope needs cargo (https://rustup.rs), or GLYPHSCOPE_BIN naming a built binary"
    say "building: cargo build --release"
    t0=$(now_ms)
    # cargo's own output goes to stdout with the progress: stderr is kept for the one
    # line that says why the report was refused or failed.
    cargo build --release --offline 2>&1 || cargo build --release 2>&1 \
        || fail "cargo build --release failed (its output is above)"
    build_time=$(since "$t0")
    bin=target/release/glyphscope
    build_line="\`cargo build --release\` (\`--offline\` first)"
fi

say "checking the adapter: glyphscope info --gpu --require-hardware"
# A CPU implementation is refused by the binary itself (wgpu's device type Cpu): its one
# line on stderr, exit 2.
adapter_report=$("$bin" info --gpu --require-hardware) || exit 2
field() { sed -n "s/^$1: //p" <<<"$adapter_report"; }
name=$(field name)
slug=$(tr '[:upper:]' '[:lower:]' <<<"$name" | sed 's/[^a-z0-9]\{1,\}/-/g; s/^-//; s/-$//')
[ -n "$slug" ] || fail "the adapter reports no name"
out=docs/bench/gpu/$slug
say "adapter: $(field adapter); writing $out/"
rm -rf "$out"
mkdir -p "$out/render"
# The pictures of the page add nothing the statistics and their error figures do not
# say (2 MB a run): they are drawn into a scratch folder, removed at the end.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

rows=()
# The README, written again after each step, so that a run cut short (a lent machine's
# time ends) still says what it measured.
write_readme() {
    {
        echo "# glyphscope on $name"
        echo
        echo "Written by \`bash tools/gpu-report.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'), commit" \
            "$(git rev-parse --short HEAD 2>/dev/null || echo unknown), on a machine of" \
            "$(nproc) CPU cores. The adapter, as \`glyphscope info --gpu\` reports it:"
        echo
        while IFS= read -r line; do echo "    $line"; done <<<"$adapter_report"
        echo
        echo "The figures belong to this adapter alone: compare methods by their ratios in one"
        echo "run (see [docs/bench.md](../../../bench.md#a-real-gpu-in-one-command)). The"
        echo "adapter's class, and what its ratios can tell, is the last line above."
        echo
        echo "| step | command | wall time |"
        echo "|---|---|---:|"
        echo "| build | $build_line | $build_time |"
        printf '%s\n' "${rows[@]}"
        echo "| all | \`bash tools/gpu-report.sh\` | $(since "$started") |"
        echo
        echo "The outputs: \`render/METHOD.json\`, each method's \`render --stats\` on the page, its"
        echo "error against the reference included;"
        echo "[motion-drift-x/motion.md](motion-drift-x/motion.md) (with its CSV, JSON, plot and"
        echo "animated picture); [bench/bench.md](bench/bench.md) (with its CSV, JSON and plots)."
    } >"$out/README.md"
}

# step TITLE ARGS...: runs the binary with ARGS, saying so, and records its wall time
# (or its failure) in the README.
step() {
    local title=$1
    shift
    say "$title: glyphscope $*"
    local t0 rc=0
    t0=$(now_ms)
    "$bin" "$@" || rc=$?
    if [ "$rc" -ne 0 ]; then
        rows+=("| $title | \`glyphscope $*\` | failed (exit $rc) after $(since "$t0") |")
        write_readme
        fail "step '$title' failed (exit $rc): see its output above"
    fi
    rows+=("| $title | \`glyphscope $*\` | $(since "$t0") |")
    write_readme
}

# The quick steps first: a run cut short keeps the most.
mapfile -t methods < <(glyphscope_methods "$bin")
[ ${#methods[@]} -gt 0 ] || fail "glyphscope render --help lists no methods (tools/methods.sh reads it)"
for method in "${methods[@]}"; do
    step "render $method" render --case page --method "$method" --out "$scratch/$method.png" \
        --error-image "$scratch/$method-error.png" --stats "$out/render/$method.json"
done
step "motion drift" "${motion_args[@]}" --out "$out/motion-drift-x"
step "quick bench" "${bench_args[@]}" --out "$out/bench"

# The full bench where the lent time allows (GPU_REPORT_BUDGET_S, the seconds the whole
# report may take: 14 minutes by default, a lent machine's 15 less its start), cut at the
# budget; the README says whether it ran, and why not.
budget_s=${GPU_REPORT_BUDGET_S:-840}
[[ "$budget_s" =~ ^[0-9]+$ ]] || fail "GPU_REPORT_BUDGET_S=$budget_s is not a number of seconds"
left_s=$((budget_s - ($(now_ms) - started) / 1000))
# Below this, the full run (every scene, every setting, each ratio settled) cannot end.
full_needs_s=240
if [ "$left_s" -ge "$full_needs_s" ]; then
    say "full bench, within the ${left_s} s left: glyphscope bench"
    t0=$(now_ms)
    rc=0
    timeout "$left_s" "$bin" bench --out "$out/bench-full" || rc=$?
    case $rc in
        0) rows+=("| full bench | \`glyphscope bench\` ([bench-full/bench.md](bench-full/bench.md)) | $(since "$t0") |") ;;
        124) rows+=("| full bench | \`glyphscope bench\`: cut at the budget (GPU_REPORT_BUDGET_S=$budget_s) | $(since "$t0") |") ;;
        *) rows+=("| full bench | \`glyphscope bench\` failed (exit $rc) | $(since "$t0") |") ;;
    esac
else
    rows+=("| full bench | not run: ${left_s} s of the ${budget_s} s budget (GPU_REPORT_BUDGET_S) were left, and it needs ${full_needs_s} s or more | — |")
fi
write_readme
say "done in $(since "$started"): $out/README.md"
