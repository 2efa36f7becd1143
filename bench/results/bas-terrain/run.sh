#!/bin/bash
# The DEM runs of bas-terrain.md, from the repository root:
#   bench/results/bas-terrain/run.sh build/test/bench/swarmplan-bench OUTDIR seeded|paper
# One query per DEM: the long query of terrain-yardsticks (middle row, first to last usable
# column, 1 above ground + clearance 1), coordinates printed to full precision.
BIN=$1; OUT=$2; INIT=$3; shift 3; EXTRA=("$@")
T=${SWARMPLAN_BENCHMARKS:-../shared/benchmarks}/terrain
mkdir -p $OUT
P=""
for p in bas lfs-bas aco-bas sio-bas multi-bas; do P="$P --planner $p --param $p.init=$INIT"; if [ "$INIT" = paper ]; then P="$P --param $p.reject_infeasible=false"; fi; done
run() { nice -n 5 $BIN $P --map $T/$1 --start=$2 --goal=$3 --clearance 1 --runs 3 --seed 1 --time-budget 1 --csv $OUT/$1.$INIT.csv --markdown $OUT/$1.$INIT.md "${EXTRA[@]}" 2> $OUT/$1.$INIT.err; }
run alps_tiny.asc 9.331388888982,46.812500000010004,788.0 9.34972222233,46.812500000010004,731.0
run alps_small.asc 9.375833333462,46.895000000075996,2742.0 9.39277777792,46.895000000075996,2001.0
run alps_medium.asc 9.339722222322,46.91805555565,1847.0 9.369722222345999,46.91805555565,1627.0
run DEM-kootenai_37x50_1x1.asc 556440.5,5394950.5,544.289978027344 556489.5,5394950.5,540.909973144531
run west_bijou_gully.asc 559748.5,4380353.5,1708.9817572699653 559784.5,4380353.5,1705.357449001736
