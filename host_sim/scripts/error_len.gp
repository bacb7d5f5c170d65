# error_len.gp - chart 2: error versus subdivision length, with the analytic
# bound of affine segments K L^2 (K = max over the scene's pixels of
# |(du/dx, dv/dx)| |q'| / (4 q)).
# Data: error_len.dat, one block per scene: L err_max err_p99 bound.
if (!exists("datadir")) datadir = "build-bench-host"
if (!exists("outdir")) outdir = "docs/bench"
scenes = "floor floor_rolled cube tunnel small_tris quad_near"
set terminal pngcairo size 1500,950 font ",10"
set output outdir."/error_len.png"
set multiplot layout 2,3 title "fixel: texel error vs segment length L (L = 1 is exact; dashed: bound L^2 |u'| |q'| / 4q)"
set logscale xy
set format y "10^{%L}"
set xtics (1, 4, 8, 16, 32, 64)
set xrange [0.8:80]
set xlabel "L, pixels between exact divisions"
set ylabel "level-0 texels"
set grid
set key top left font ",8"
f = datadir."/error_len.dat"
do for [i=0:5] {
    set title word(scenes, i+1) noenhanced
    plot f index i using 1:2 with linespoints pt 7 lc rgb "#c03030" title "max", \
         f index i using 1:3 with linespoints pt 6 lc rgb "#3050c0" title "p99", \
         f index i using 1:4 with lines dt 2 lw 2 lc rgb "#202020" title "bound"
}
unset multiplot
