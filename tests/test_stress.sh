#!/bin/bash
# The stress matrix's quick subset (tests/stress.sh --quick; the whole matrix is `make stress`).
exec "$(dirname "$0")/stress.sh" "${WG_BIN:?}" --quick
