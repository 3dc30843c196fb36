#!/usr/bin/env bash
# Issue #30 defects 1-15 reproduced with a given binary: run it with the binary of a220f30
# (before) and of main (after) to see each defect and its fix side by side.
#   bash tools/reproduce_issue30.sh path/to/stormer [REPO]
B=$1; R=${2:-$(cd "$(dirname "$0")/.." && pwd)}
d=$(mktemp -d); cd "$d" || exit 1
run() { echo "--- $1"; shift; timeout 120 "$@" >out.txt 2>err.txt; echo "exit $?"; tail -n 3 err.txt; tail -n 4 out.txt; }
run "1 section on 1 dof" $B run pendulum --section "theta = 0, omega > 0" --out p.csv
( ulimit -v 8000000; run "2 newton on 6000 particles" $B run $R/scenes/particles-bottle.toml --method gauss_legendre4 --solver newton --t-end 0.02 --out pb.csv )
sed 's/^alpha = 30.0 /alpha = 0.5  /' $R/scenes/free-kick.toml > fk.toml; grep -c "alpha = 0.5" fk.toml
run "4 free kick alpha 0.5" $B run fk.toml --out fk.csv
run "6 tiny dt guess" $B run harmonic --method dop853 --rtol 1e-8 --dt 1e-16 --out h6.csv
run "7a ensemble digits" $B ensemble harmonic --vary x=1:2:3 --show energy_error --out e7
run "7b scan order" $B scan harmonic --method rk4 --steps 14,12 --out s7
printf 'name = "g01"\nfamily = "composition"\norder = 2\ngamma = ["0", "1"]\n' > g01.toml
run "8 composition gamma 0,1" $B verify g01.toml
run "11 drifts sum 1+1e-8" $B verify $R/app/tests/bad_input/method_splitting_sum_off_by_1e-8.toml
$B scene show harmonic > h-state.svg 2>/dev/null; cp h-state.svg h-state.before
run "12 output over input" $B run h-state.svg --out h.csv
cmp -s h-state.svg h-state.before && echo "12: input intact" || echo "12: INPUT REPLACED"
echo "not a method" > rk4
run "13 stray file rk4" $B run harmonic --method rk4 --out h13.csv
rm rk4
( ulimit -v 4000000; run "14 save-at 1e8 times" /usr/bin/time -f "%e s %M KB" $B run harmonic --save-at 0:1.0000001e-7:10 --out s14.csv )
run "15 tiny t" $B run harmonic --t-end 1e-300 --out h15.csv
run "15 split none" $B run outer-solar-system --split none --t-end 1000 --out o15.csv
run "9 boris bottle dt 0.02" $B run magnetic-bottle --method boris --dt 0.02 --out b9.csv
rm -rf "$d"
