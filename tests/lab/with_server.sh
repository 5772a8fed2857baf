#!/usr/bin/env bash
# Runs a command (the lab store's C++ tests) with a private PostgreSQL server started for it and
# stopped after it (pg_server.sh), its exit status the command's.
# Usage: with_server.sh COMMAND [ARG...]
set -euo pipefail
source "$(dirname "$0")/pg_server.sh"
pg_start
"$@"
