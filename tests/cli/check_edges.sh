#!/usr/bin/env bash
# The edge families through the CLI: pairs of known position (tests/support/edge_cases.hpp, written
# as JSON Lines by edge_cases_jsonl) answered by `relpos batch --evidence full`, every position
# compared and every certificate checked by `relpos verify` (tests/cli/check_examples.sh).
#
# Usage: tests/cli/check_edges.sh PATH/TO/relpos PATH/TO/edge_cases_jsonl REPO_ROOT
set -u
if [ $# -ne 3 ]; then
  echo "usage: $0 PATH/TO/relpos PATH/TO/edge_cases_jsonl REPO_ROOT" >&2
  exit 2
fi
input=$(mktemp)
trap 'rm -f "$input"' EXIT
"$2" >"$input" || { echo "check_edges: the generator failed" >&2; exit 2; }
exec "$3/tests/cli/check_examples.sh" "$1" "$3" "$input"
