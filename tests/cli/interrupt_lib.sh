# Shared by the Ctrl+C tests (interrupt_export_test.sh, interrupt_runs_test.sh,
# interrupt_gl_runs_test.sh, bench_cli_test.sh): sourced, not run.

# interrupt_when PATTERN FILE PID SIGNAL...: waits (60 s at most) until FILE, the stderr of
# process PID (a child of this shell: not inside $(...)), has a line matching the extended regex
# PATTERN, sends each SIGNAL 300 ms apart (closer, the command takes a second as the first relayed
# again: core::InterruptStop::SAME_REQUEST_NS), waits for the process and sets interrupted_status to its
# exit status.
interrupt_when() {
    local pattern=$1 file=$2 pid=$3 i sig
    shift 3
    for ((i = 0; i < 3000; ++i)); do
        grep -Eq "$pattern" "$file" 2>/dev/null && break
        sleep 0.02
    done
    for sig in "$@"; do kill -s "$sig" "$pid"; sleep 0.3; done
    wait "$pid"
    interrupted_status=$?
}
