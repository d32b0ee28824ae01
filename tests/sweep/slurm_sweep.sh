#!/bin/bash
# A 4-scene sweep run by a real Slurm as a job array, on a one-node cluster
# on loopback that this script starts and stops (tests/test_sweep_slurm.pf
# runs it; the test then checks the table the sweep collected).
#
#   tests/sweep/slurm_sweep.sh WORKDIR
#
# 1. Installs the Debian packages slurm-wlm and munge when slurmctld, slurmd,
#    sbatch or munged are missing (apt-get as root, else sudo -n).
# 2. In a new temporary directory (/tmp/impact-slurm.XXXXXX: the munge socket
#    path must stay short): a munge key and munged; a minimal slurm.conf (one
#    node with this machine's cores, one partition, free ports on 127.0.0.1,
#    no cgroups, no accounting); slurmctld and slurmd, all in the foreground
#    as background jobs of this script, so that their process ids are known.
# 3. tools/sweep init WORKDIR/sweep with tests/sweep/template.nml and
#    mass x velocity = 2 x 2 scenes, then tools/sweep slurm --submit --wait
#    asking one scene a task; the cluster's MaxArraySize = 2 (task ids 0
#    and 1, read by the sweep from scontrol show config) makes it 2 array
#    tasks of 2 scenes, at most 2 at once; it collects WORKDIR/sweep/table.dat
#    when the array has ended.
# 4. Stops slurmd, slurmctld and munged by the process ids it started (also
#    on failure or interruption), cancels its job first if it is still there,
#    and removes the temporary directory.
#
# Exit status 0 when the array ran and all 4 scenes completed; 1 otherwise,
# with the daemons' logs on standard error. Takes 15-30 s once the packages
# are installed.
set -u

work=${1:?usage: slurm_sweep.sh WORKDIR}
repo=$(cd "$(dirname "$0")/../.." && pwd)
deadline=120          # s: the whole array, at most
mkdir -p "$work"
work=$(cd "$work" && pwd)

say() { echo "slurm_sweep: $*"; }
die() { echo "slurm_sweep: error: $*" >&2; exit 1; }

# ---- 1. the packages
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null \
   || ! command -v sbatch >/dev/null || ! command -v munged >/dev/null; then
    if [ "$(id -u)" -eq 0 ]; then as_root=""
    elif command -v sudo >/dev/null; then as_root="sudo -n"
    else die "slurm-wlm and munge are missing and this is not root: apt-get install slurm-wlm munge"
    fi
    say "installing slurm-wlm and munge (apt-get)"
    export DEBIAN_FRONTEND=noninteractive
    $as_root apt-get install -y --no-install-recommends slurm-wlm munge >/dev/null \
        || { $as_root apt-get update >/dev/null \
             && $as_root apt-get install -y --no-install-recommends slurm-wlm munge >/dev/null; } \
        || die "apt-get install slurm-wlm munge failed"
fi
[ -x "$repo/impact" ] || die "$repo/impact is missing: build it with make"

# ---- 2. the cluster
tmp=$(mktemp -d /tmp/impact-slurm.XXXXXX) || die "mktemp failed"
chmod 755 "$tmp"
mkdir -p "$tmp/munge" "$tmp/state" "$tmp/spool" "$tmp/log"
chmod 755 "$tmp/munge"
pids=()
job=""

stop() {
    if [ -n "$job" ] && [ -n "${SLURM_CONF:-}" ]; then scancel "$job" 2>/dev/null; fi
    # slurmd, slurmctld, munged: the reverse of the order they started in
    for (( k=${#pids[@]}-1; k>=0; k-- )); do
        kill "${pids[k]}" 2>/dev/null
        for _ in $(seq 50); do kill -0 "${pids[k]}" 2>/dev/null || break; sleep 0.1; done
        kill -9 "${pids[k]}" 2>/dev/null
        wait "${pids[k]}" 2>/dev/null
    done
    pids=()
    rm -rf "$tmp"
}
logs() {
    for f in "$tmp"/log/*.log "$tmp"/munge/munged.log; do
        [ -f "$f" ] && { echo "---- $f (last lines)"; tail -n 15 "$f"; }
    done >&2
}
trap 'stop' EXIT
trap 'exit 1' INT TERM

ports=$(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(" ".join(str(x.getsockname()[1]) for x in s))') || die "no free ports"
read -r ctld_port slurmd_port <<< "$ports"
cpus=$(nproc)

mungekey --create --keyfile="$tmp/munge/munge.key" 2>/dev/null \
    || { dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 2>/dev/null && chmod 600 "$tmp/munge/munge.key"; } \
    || die "cannot make a munge key"
munged --foreground --force --socket="$tmp/munge/munge.socket" --key-file="$tmp/munge/munge.key" \
    --log-file="$tmp/munge/munged.log" --pid-file="$tmp/munge/munged.pid" \
    --seed-file="$tmp/munge/munged.seed" > "$tmp/munge/munged.out" 2>&1 &
pids+=($!)

cat > "$tmp/slurm.conf" <<EOF
# one-node Slurm on loopback for tests/sweep/slurm_sweep.sh
ClusterName=impacttest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$(id -un)
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
SlurmdTimeout=30
NodeName=impactnode NodeAddr=127.0.0.1 NodeHostname=localhost CPUs=$cpus State=UNKNOWN
MaxArraySize=2
PartitionName=impact Nodes=impactnode Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"

for _ in $(seq 50); do [ -S "$tmp/munge/munge.socket" ] && break; sleep 0.1; done
[ -S "$tmp/munge/munge.socket" ] || { logs; die "munged did not start"; }
slurmctld -D -f "$SLURM_CONF" > "$tmp/log/slurmctld.out" 2>&1 &
pids+=($!)
sleep 1
slurmd -D -N impactnode -f "$SLURM_CONF" > "$tmp/log/slurmd.out" 2>&1 &
pids+=($!)
say "munged, slurmctld, slurmd started: pids ${pids[*]}; ports $ctld_port, $slurmd_port; $cpus cpus"

ready=""
for _ in $(seq 60); do
    state=$(sinfo -h -n impactnode -o %T 2>/dev/null)
    case "$state" in idle*|mix*|alloc*) ready=yes; break ;; esac
    sleep 0.5
done
[ -n "$ready" ] || { logs; die "the node did not come up (state: '${state:-none}')"; }
say "node impactnode is $state"

# ---- 3. the sweep, as a job array
rm -rf "$work/sweep"
"$repo/tools/sweep" init "$work/sweep" --deck "$repo/tests/sweep/template.nml" \
    --vary impactor.mass=0.1,0.243 --vary impactor.velocity=1.5,3.0 || die "tools/sweep init failed"
timeout "$deadline" "$repo/tools/sweep" slurm "$work/sweep" --max-running 2 --scenes-per-task 1 \
    --poll 1 --time 00:05:00 --job-name impact-test --submit --wait > "$work/submit.log" 2>&1
code=$?
cat "$work/submit.log"
job=$(sed -n 's/^sweep: submitted job array \([0-9]*\).*/\1/p' "$work/submit.log")
if [ "$code" -ne 0 ]; then
    logs
    die "the sweep did not complete (tools/sweep slurm exit status $code)"
fi
job=""
say "the job array ran; table: $work/sweep/table.dat"
exit 0
