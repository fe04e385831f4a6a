#!/bin/sh
# Error against CPU time from bench_accuracy's CSV (one panel per error): every setting a labelled
# point, the Pareto front (the settings no other setting beats on both CPU time and error) joined in
# red, the defaults circled. The reference has no error by construction: it is left out of the panels
# and its CPU time is given in the title.
#   bench/accuracy_plot.sh accuracy.csv accuracy.svg
set -eu
if [ $# -ne 2 ]; then
    echo "usage: $0 ACCURACY.csv OUT.svg (the CSV from bench_accuracy --out)" >&2
    exit 2
fi
csv=$1
svg=$2
[ -r "$csv" ] || { echo "$0: cannot read $csv" >&2; exit 1; }
command -v gnuplot >/dev/null || { echo "$0: gnuplot not found (apt-get install gnuplot-nox)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Column of a header name in the CSV.
column() {
    head -n 1 "$csv" | tr ',' '\n' | grep -n -x "$1" | cut -d: -f1 | grep . ||
        { echo "$0: $csv has no column $1 (not bench_accuracy's CSV?)" >&2; exit 1; }
}
setting=$(column setting)
cpu=$(column cpu_s_per_run_median)
status=$(column status)
reference_cpu=$(awk -F, -v s="$setting" -v c="$cpu" '$s == "reference" { print $c }' "$csv")

panels=""
for metric in runout_err_median_m dist50_err_m pf50_err tree_energy_err_median; do
    m=$(column $metric)
    # cpu,error,setting of every finished setting but the reference, cheapest first
    awk -F, -v OFS=, -v s="$setting" -v c="$cpu" -v e="$m" -v st="$status" \
        'NR > 1 && $st == "ok" && $s != "reference" { print $c, $e, $s }' "$csv" | sort -t, -k1,1g -k2,2g >"$tmp/$metric.dat"
    # On the front: more accurate than every cheaper setting.
    awk -F, 'NR == 1 || $2 < best { print; best = $2 }' "$tmp/$metric.dat" >"$tmp/$metric.front"
    grep ',defaults$' "$tmp/$metric.dat" >"$tmp/$metric.defaults" || true
    case $metric in
        runout_err_median_m) title="paired run-out error, median over runs"; unit="m" ;;
        dist50_err_m) title="error in Dist50 (median run-out)"; unit="m" ;;
        pf50_err) title="error in PF50 (Eq. 26)"; unit="absolute" ;;
        tree_energy_err_median) title="energy taken by a single tree, median over cases"; unit="relative" ;;
    esac
    if [ ! -s "$tmp/$metric.dat" ]; then
        echo "$0: no finished setting besides the reference in $csv" >&2
        exit 1
    fi
    defaults=""
    [ -s "$tmp/$metric.defaults" ] && defaults=", '$tmp/$metric.defaults' using 1:2 with points pt 6 ps 2.5 lw 2 lc rgb '#1f5fbf' title 'defaults'"
    panels="$panels
set title '$title'
set ylabel 'error ($unit)'
plot '$tmp/$metric.dat' using 1:2 with points pt 7 ps 0.7 lc rgb 'gray40' title 'settings', \\
     '' using 1:2:3 with labels left offset 0.6,0.4 font ',7' notitle, \\
     '$tmp/$metric.front' using 1:2 with linespoints lw 2 pt 7 ps 0.9 lc rgb '#c0392b' title 'Pareto front'$defaults"
done

gnuplot <<EOF
set terminal svg size 1200,900 dynamic font 'sans,11'
set output '$svg'
set datafile separator ','
set grid
set logscale x
set yrange [0:*]
set offsets 0, 0, graph 0.3, 0  # headroom for the key and the labels
set key top right
set xlabel 'CPU time per forested run, median (s)'
set multiplot layout 2,2 title 'Error against CPU time, each knob changed alone from the defaults (reference: ${reference_cpu:-?} s per run)'
$panels
unset multiplot
EOF
echo "$svg"
