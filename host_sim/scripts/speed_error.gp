# speed_error.gp - chart 1: texel error versus cost per scene, Pareto front.
# gnuplot -e "datadir='build-bench-host'; outdir='docs/bench'" speed_error.gp
# Data (fixel-bench accuracy --plot-dir): speed_error.dat, one block per
# scene (point filter): cost err_max err_p99 on_front method.
if (!exists("datadir")) datadir = "build-bench-host"
if (!exists("outdir")) outdir = "docs/bench"
scenes = "floor floor_rolled cube tunnel small_tris quad_near"
set terminal pngcairo size 1500,950 font ",10"
set output outdir."/speed_error.png"
set multiplot layout 2,3 title "fixel: texel-coordinate error vs cost (point filter, 320x240; line = Pareto front of max error)"
set logscale y
set format y "10^{%L}"
set xlabel "instructions / covered pixel (Cortex-M4 -O2; host where missing)"
set ylabel "|(u,v) - exact| in level-0 texels"
set grid
set key top right font ",8"
f = datadir."/speed_error.dat"
do for [i=0:5] {
    set title word(scenes, i+1) noenhanced
    plot f index i using 1:2 with points pt 7 ps 1.2 lc rgb "#c03030" title "max", \
         f index i using 1:3 with points pt 6 ps 1.2 lc rgb "#3050c0" title "p99", \
         f index i using ($4 == 1 ? $1 : 1/0):2 smooth unique with lines lw 2 lc rgb "#c03030" title "front (max)", \
         f index i using 1:2:5 with labels offset char 0.6,0.6 left font ",7" noenhanced notitle
}
unset multiplot
