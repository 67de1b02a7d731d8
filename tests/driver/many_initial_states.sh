#!/usr/bin/env bash
# A deck that gives the initial state of 50000 elements one by one and of a set 20000 times
# (results mapped from an earlier run): interphase-check-deck reads it in linear time (ctest
# check_deck_initial_many, with a timeout; it took minutes when every data line copied the lines
# before it).
#   many_initial_states.sh CHECK_DECK WORKDIR
set -eo pipefail
check_deck=$1
work=$2
mkdir -p "$work"
deck=$work/many_initial_states.inp
{
  printf '*HEADING\nmany initial states\n'
  printf '*COHESIVE SECTION, ELSET=JOINT, MATERIAL=M, RESPONSE=TRACTION SEPARATION, THICKNESS=SPECIFIED\n 1.,\n'
  printf '*MATERIAL, NAME=M\n*USER MATERIAL, CONSTANTS=9, UNSYMM\n'
  printf ' 1., 1., 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.6974268\n 198.7577640\n*DEPVAR\n 4,\n'
  printf '*INITIAL CONDITIONS, TYPE=SOLUTION\n'
  awk 'BEGIN { for (i = 1; i <= 50000; i++) printf " %d, 0.5, 0.001, 0., 2.\n", i }'
  printf '*INITIAL CONDITIONS, TYPE=SOLUTION\n'
  awk 'BEGIN { for (i = 1; i <= 20000; i++) printf " JOINT, 0.5, 0.001, 0., 2.\n" }'
  printf '*STEP\n*STATIC\n 0.01, 1.\n*END STEP\n'
} > "$deck"
"$check_deck" "$deck"
