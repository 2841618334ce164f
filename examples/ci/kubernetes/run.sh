#!/bin/sh
# Runs the snapshot suite on Kubernetes: a fresh volume, the Indexed Job of shards, the merge,
# then copies the report to ./snapshot-report. Exit status: the merge's (0 all match, 1 a case
# differs or lacks a golden, 2 bad input or a missing shard).
set -eu
cd "$(dirname "$0")"
kubectl delete --ignore-not-found job/robot-snapshots-merge job/robot-snapshots pvc/robot-snapshots
kubectl apply -f snapshots-job.yaml
kubectl wait --for=condition=complete --timeout=60m job/robot-snapshots
kubectl apply -f merge-job.yaml
# the merge ends as Complete or Failed; wait for either
until [ -n "$(kubectl get job/robot-snapshots-merge -o jsonpath='{.status.succeeded}{.status.failed}')" ]; do
  sleep 5
done
kubectl logs job/robot-snapshots-merge
# a pod that mounts the volume, to copy the report out of it
kubectl run robot-snapshots-fetch --image=debian:12 --restart=Never --overrides='{"spec": {
  "volumes": [{"name": "results", "persistentVolumeClaim": {"claimName": "robot-snapshots"}}],
  "containers": [{"name": "fetch", "image": "debian:12", "command": ["sleep", "600"],
                  "volumeMounts": [{"name": "results", "mountPath": "/results"}]}]}}'
kubectl wait --for=condition=ready --timeout=5m pod/robot-snapshots-fetch
kubectl cp robot-snapshots-fetch:/results/report ./snapshot-report
kubectl delete pod/robot-snapshots-fetch --wait=false
[ "$(kubectl get job/robot-snapshots-merge -o jsonpath='{.status.succeeded}')" = 1 ]
