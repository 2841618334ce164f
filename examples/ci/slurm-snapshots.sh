#!/bin/bash
# Runs the snapshot suite as a Slurm job array of 16 shards and a merge job that starts when they
# have all ended. Run it on a login node from the robot repository (on a file system the compute
# nodes share); urdfsnap must be installed on the nodes (apt-get install ./urdfsnap_<version>_amd64.deb,
# the package scripts/package.sh makes). Each task reads its shard from SLURM_ARRAY_TASK_ID,
# SLURM_ARRAY_TASK_MIN and SLURM_ARRAY_TASK_COUNT.
set -euo pipefail
suite=test/snapshots/suite.yaml
out=snapshots-$(date +%Y%m%d-%H%M%S)
mkdir -p "$out"
# exit status 1 (a case differs) is a result for the merge, not a failed task
array=$(sbatch --parsable --job-name=robot-snapshots --array=1-16 --cpus-per-task=2 --mem=1G \
  --time=00:30:00 --output="$out/shard-%a.log" \
  --wrap="urdfsnap snapshot check $suite --results $out/shard-\$SLURM_ARRAY_TASK_ID/results.json --report $out/shard-\$SLURM_ARRAY_TASK_ID/report || [ \$? -eq 1 ]")
merge=$(sbatch --parsable --job-name=robot-snapshots-merge --dependency=afterany:"$array" \
  --time=00:10:00 --output="$out/merge.log" \
  --wrap="urdfsnap snapshot merge $out/shard-*/results.json --report $out/report --junit $out/junit.xml")
echo "shards: job $array, merge: job $merge; the report will be $out/report/index.html ($out/merge.log says how it went)"
