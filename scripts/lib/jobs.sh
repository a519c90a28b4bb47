# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: how many compile (or test) jobs to
# run at once. One per processor, as ninja and ./test.sh do, but at most one per 2 GiB of
# available memory: an instrumented kernel file takes up to 1.3 GiB to compile.
machine_jobs() {
  local cpus mem
  cpus=$(nproc)
  mem=$(awk '/^MemAvailable:/ { print int($2 / 2097152) }' /proc/meminfo 2>/dev/null || true)
  [[ "$mem" =~ ^[0-9]+$ ]] && ((mem >= 1)) || mem=1
  echo $((cpus < mem ? cpus : mem))
}
