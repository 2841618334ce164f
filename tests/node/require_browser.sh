# Sourced by the browser tests' shell scripts: require_browser ROOT returns when headless Chromium
# and the npm test tooling (scripts/node-deps.sh) are there; without chromium it exits 77 (ctest's
# skip), or 1 when CI=true, where a browser test must run.
require_browser() {
  if [ ! -x /usr/bin/chromium ]; then
    echo "no /usr/bin/chromium (scripts/deps.sh installs it)"
    [ "${CI:-}" = true ] && exit 1
    exit 77
  fi
  "$1/scripts/node-deps.sh"
}
