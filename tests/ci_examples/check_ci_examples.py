#!/usr/bin/env python3
"""The CI setups docs/snapshot-testing.md shows (examples/ci/) are the files in the repository, they
parse, and they work: each one is played here the way its engine would run it, with its own commands, against a
small suite with one failing case and the urdfsnap binary on PATH (installing the package is the
one step left out):

  GitHub Actions  every matrix job's steps (${{ matrix.shard }} and ${{ strategy.job-total }}
                  filled in), artifacts uploaded and downloaded as upload/download-artifact do,
                  then the merge job
  GitLab          every `parallel:` job's script with CI_NODE_INDEX / CI_NODE_TOTAL, its
                  artifacts paths collected, then the merge job
  Kubernetes      every index of the Indexed Job's container command with JOB_COMPLETION_INDEX
                  and the container's env, the shared volume a folder, then the merge Job's
  Slurm           the submit script with a stand-in `sbatch` that runs the array's tasks (with
                  SLURM_ARRAY_TASK_ID, _MIN, _COUNT) and then the dependent merge job

Each must end in a merged report and JUnit file holding every case once, the failing one failed.

usage: check_ci_examples.py URDFSNAP SOURCE_DIR
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

import yaml

CASES = 8


def fail(message):
    sys.exit(f"check_ci_examples.py: {message}")


def run(command, cwd, env, shell="/bin/bash"):
    """Runs `command` with `shell` -c; returns its exit status (output shown on failure)."""
    result = subprocess.run([shell, "-c", command], cwd=cwd, env=env, capture_output=True, text=True)
    if result.returncode not in (0, 1):
        fail(f"`{command}` exited {result.returncode}:\n{result.stdout}{result.stderr}")
    return result.returncode


def make_workspace(urdfsnap, source, path):
    """A robot repository: urdf/mrm.urdf and test/snapshots/ with CASES cases and goldens, one of
    which (drifted) shows another pose."""
    os.makedirs(os.path.join(path, "urdf"))
    os.makedirs(os.path.join(path, "test", "snapshots"))
    shutil.copy(os.path.join(source, "models/mrm_description/urdf/mrm.urdf"), os.path.join(path, "urdf"))
    lines = ["defaults:", "  model: ../../urdf/mrm.urdf", "  size: 160x120", "cases:"]
    for i in range(CASES - 1):
        lines += [f"  - name: view_{i}", f"    yaw: {0.4 * i:.1f}"]
    lines += ["  - name: drifted", "    joints: {link_01__link_02: 0.7}"]
    suite = os.path.join(path, "test", "snapshots", "suite.yaml")
    with open(suite, "w") as f:
        f.write("\n".join(lines) + "\n")
    subprocess.run([urdfsnap, "snapshot", "update", suite, "--no-shard"], check=True,
                   stdout=subprocess.DEVNULL)
    shutil.copy(os.path.join(path, "test/snapshots/view_0.png"), os.path.join(path, "test/snapshots/drifted.png"))


def check_merged(engine, junit, report):
    """The merged JUnit holds every case once with only 'drifted' failed; the report exists."""
    if not os.path.isfile(os.path.join(report, "index.html")):
        fail(f"{engine}: no merged report {report}/index.html")
    cases = ElementTree.parse(junit).getroot().iter("testcase")
    names = {}
    for case in cases:
        names[case.get("name")] = names.get(case.get("name"), 0) + (case.find("failure") is not None) * 10 + 1
    expected = {f"view_{i}": 1 for i in range(CASES - 1)} | {"drifted": 11}
    if names != expected:
        fail(f"{engine}: merged JUnit cases {names}, expected {expected}")
    print(f"{engine}: {CASES} cases merged, 'drifted' failed")


def expand_github(text, values):
    def value(match):
        expression = match.group(1).strip()
        if expression not in values:
            fail(f"github-actions.yml: no value for ${{{{ {expression} }}}} in this test")
        return str(values[expression])
    return re.sub(r"\$\{\{(.*?)\}\}", value, text)


def play_github(workflow, workspace, env, work):
    jobs = workflow["jobs"]
    shard, merge = jobs["shard"], jobs["merge"]
    if merge.get("needs") != "shard" or "cancelled()" not in merge.get("if", ""):
        fail("github-actions.yml: the merge job must need the shards and run unless cancelled")
    matrix = shard["strategy"]["matrix"]["shard"]
    if matrix != list(range(1, len(matrix) + 1)):
        fail(f"github-actions.yml: matrix.shard {matrix} is not 1..N")
    env = dict(env, **workflow["env"])
    artifacts = os.path.join(work, "github-artifacts")

    def play_job(job, folder, values):
        failed = False
        for step in job["steps"]:
            uses = step.get("uses", "")
            if failed and "cancelled()" not in step.get("if", ""):
                continue
            if step.get("name") == "Install urdfsnap" or uses.startswith("actions/checkout"):
                continue
            if uses.startswith("actions/upload-artifact"):
                name = expand_github(step["with"]["name"], values)
                shutil.copytree(os.path.join(folder, step["with"]["path"]), os.path.join(artifacts, name))
            elif uses.startswith("actions/download-artifact"):
                for found in glob.glob(os.path.join(artifacts, step["with"]["pattern"])):
                    shutil.copytree(found, os.path.join(folder, step["with"]["path"], os.path.basename(found)))
            else:
                failed |= run(expand_github(step["run"], values), folder, env) != 0
        return failed

    for k in matrix:
        folder = os.path.join(work, f"github-shard-{k}")
        shutil.copytree(workspace, folder)
        play_job(shard, folder, {"matrix.shard": k, "strategy.job-total": len(matrix), "!cancelled()": "true"})
    folder = os.path.join(work, "github-merge")
    os.makedirs(folder)
    if not play_job(merge, folder, {"!cancelled()": "true"}):
        fail("github-actions.yml: the merge job passed with a failing case")
    check_merged("GitHub Actions", os.path.join(folder, "snapshot-junit.xml"), os.path.join(artifacts, "snapshot-report"))


def play_gitlab(ci, workspace, env, work):
    jobs = ci["snapshots"], ci["snapshot-report"]
    shards, merge = jobs
    if merge.get("when") != "always" or merge["artifacts"]["reports"]["junit"] != "snapshot-junit.xml":
        fail("gitlab-ci.yml: the report job must run always and hand GitLab its JUnit file")
    count = shards["parallel"]
    env = dict(env, **ci["variables"])
    merge_folder = os.path.join(work, "gitlab-merge")
    os.makedirs(merge_folder)
    for k in range(1, count + 1):
        folder = os.path.join(work, f"gitlab-{k}")
        shutil.copytree(workspace, folder)
        job_env = dict(env, CI_NODE_INDEX=str(k), CI_NODE_TOTAL=str(count))
        for line in shards["script"]:
            run(line, folder, job_env)
        # artifacts of the earlier stage are unpacked into the later job's checkout
        for path in shards["artifacts"]["paths"]:
            path = path.replace("$CI_NODE_INDEX", str(k))
            shutil.copytree(os.path.join(folder, path), os.path.join(merge_folder, path))
    statuses = [run(line, merge_folder, env) for line in merge["script"]]
    if statuses[-1] != 1:
        fail("gitlab-ci.yml: the report job passed with a failing case")
    check_merged("GitLab", os.path.join(merge_folder, "snapshot-junit.xml"), os.path.join(merge_folder, "snapshot-report"))


def container_of(path, kind="Job"):
    with open(path) as f:
        documents = [d for d in yaml.safe_load_all(f) if d]
    job = next(d for d in documents if d["kind"] == kind)
    return documents, job, job["spec"]["template"]["spec"]["containers"][0]


def play_kubernetes(folder, workspace, env, work):
    documents, job, container = container_of(os.path.join(folder, "snapshots-job.yaml"))
    spec = job["spec"]
    count = spec["completions"]
    container_env = {e["name"]: e["value"] for e in container.get("env", [])}
    if spec.get("completionMode") != "Indexed" or container_env.get("URDFSNAP_SHARD_COUNT") != str(count):
        fail("kubernetes: the Job must be Indexed with URDFSNAP_SHARD_COUNT equal to its completions")
    claim = next(d for d in documents if d["kind"] == "PersistentVolumeClaim")["metadata"]["name"]
    _, _, merge = container_of(os.path.join(folder, "merge-job.yaml"))
    _, merge_job, _ = container_of(os.path.join(folder, "merge-job.yaml"))
    for j, c in ((job, container), (merge_job, merge)):
        volumes = j["spec"]["template"]["spec"]["volumes"]
        if volumes[0]["persistentVolumeClaim"]["claimName"] != claim:
            fail(f"kubernetes: {j['metadata']['name']} does not mount the claim {claim}")
    volume = os.path.join(work, "kubernetes-volume")
    os.makedirs(volume)
    mount = container["volumeMounts"][0]["mountPath"]
    for index in range(count):
        pod_env = dict(env, **container_env, JOB_COMPLETION_INDEX=str(index))
        command = container["args"][0].replace(mount + "/", volume + "/")
        if run(command, workspace, pod_env, shell=container["command"][0]) != 0:
            fail(f"kubernetes: the pod of index {index} failed (a failing case must not fail it)")
    if run(merge["args"][0].replace(mount + "/", volume + "/"), workspace, env, shell=merge["command"][0]) != 1:
        fail("kubernetes: the merge passed with a failing case")
    check_merged("Kubernetes", os.path.join(volume, "junit.xml"), os.path.join(volume, "report"))


# a stand-in for Slurm's sbatch: runs an array's tasks and the dependent job at once, in order
FAKE_SBATCH = r'''#!/usr/bin/env python3
import os, subprocess, sys
options, wrap = {}, None
for argument in sys.argv[1:]:
    if argument.startswith("--wrap="):
        wrap = argument[len("--wrap="):]
    elif "=" in argument:
        key, value = argument.split("=", 1)
        options[key] = value
counter = os.path.join(os.environ["FAKE_SLURM_DIR"], "last_job")
job = int(open(counter).read()) + 1 if os.path.exists(counter) else 100
open(counter, "w").write(str(job))
tasks = [None]
if "--array" in options:
    first, last = (int(n) for n in options["--array"].split("-"))
    tasks = range(first, last + 1)
for task in tasks:
    env = dict(os.environ, SLURM_JOB_ID=str(job))
    output = options.get("--output", "slurm-%j.out").replace("%A", str(job)).replace("%j", str(job))
    if task is not None:
        env.update(SLURM_ARRAY_JOB_ID=str(job), SLURM_ARRAY_TASK_ID=str(task), SLURM_ARRAY_TASK_MIN=str(first),
                   SLURM_ARRAY_TASK_MAX=str(last), SLURM_ARRAY_TASK_COUNT=str(last - first + 1))
        output = output.replace("%a", str(task))
    with open(output, "w") as log:
        status = subprocess.run(["/bin/sh", "-c", wrap], env=env, stdout=log, stderr=log).returncode
    with open(os.path.join(os.environ["FAKE_SLURM_DIR"], "statuses"), "a") as f:
        f.write(f"{options.get('--job-name')} {task} {status}\n")
print(job if "--parsable" in sys.argv else f"Submitted batch job {job}")
'''


def play_slurm(script, workspace, env, work):
    slurm_dir = os.path.join(work, "slurm")
    os.makedirs(slurm_dir)
    sbatch = os.path.join(env["FAKE_BIN"], "sbatch")
    with open(sbatch, "w") as f:
        f.write(FAKE_SBATCH)
    os.chmod(sbatch, 0o755)
    run(f"bash {script}", workspace, dict(env, FAKE_SLURM_DIR=slurm_dir))
    with open(os.path.join(slurm_dir, "statuses")) as f:
        statuses = [line.split() for line in f]
    shards = [s for s in statuses if s[0] == "robot-snapshots"]
    if not shards or any(s[2] != "0" for s in shards):
        fail(f"slurm: array tasks {shards} (a failing case must not fail a task)")
    if statuses[-1][0] != "robot-snapshots-merge" or statuses[-1][2] != "1":
        fail(f"slurm: the merge job ended {statuses[-1]}, expected status 1 for the failing case")
    out = glob.glob(os.path.join(workspace, "snapshots-*"))[0]
    check_merged(f"Slurm ({len(shards)} array tasks)", os.path.join(out, "junit.xml"), os.path.join(out, "report"))


def check_docs_page(source):
    """Every file of examples/ci appears whole in docs/snapshot-testing.md, in a fenced block."""
    with open(os.path.join(source, "docs", "snapshot-testing.md")) as f:
        readme = f.read()
    for path in sorted(glob.glob(os.path.join(source, "examples/ci/**/*"), recursive=True)):
        if os.path.isdir(path):
            continue
        with open(path) as f:
            text = f.read()
        if f"\n{text}```" not in readme:
            fail(f"docs/snapshot-testing.md does not show {os.path.relpath(path, source)} as it is")


def main():
    urdfsnap, source = (os.path.abspath(p) for p in sys.argv[1:3])
    examples = os.path.join(source, "examples/ci")
    check_docs_page(source)
    with open(os.path.join(examples, "github-actions.yml")) as f:
        github = yaml.safe_load(f)
    with open(os.path.join(examples, "gitlab-ci.yml")) as f:
        gitlab = yaml.safe_load(f)
    work = tempfile.mkdtemp(prefix="urdfsnap_ci_examples.")
    try:
        bin_dir = os.path.join(work, "bin")
        os.makedirs(bin_dir)
        os.symlink(urdfsnap, os.path.join(bin_dir, "urdfsnap"))
        env = {k: v for k, v in os.environ.items()
               if k not in ("CI_NODE_INDEX", "CI_NODE_TOTAL", "SLURM_ARRAY_TASK_ID", "JOB_COMPLETION_INDEX",
                            "URDFSNAP_SHARD_COUNT")}
        env.update(PATH=bin_dir + os.pathsep + env["PATH"], FAKE_BIN=bin_dir)
        workspace = os.path.join(work, "robot")
        make_workspace(urdfsnap, source, workspace)
        play_github(github, workspace, env, work)
        play_gitlab(gitlab, workspace, env, work)
        play_kubernetes(os.path.join(examples, "kubernetes"), workspace, env, work)
        play_slurm(os.path.join(examples, "slurm-snapshots.sh"), workspace, env, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
