# Sourced by the bench scripts for what each needs first: $root, the repository, and $work, a
# scratch folder removed when the script exits.
# usage (in bench/<area>/<name>.sh): source "$(dirname "$0")/../bench_work.sh" NAME
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/urdfsnap_$1.XXXXXX")
trap 'rm -rf "$work"' EXIT
