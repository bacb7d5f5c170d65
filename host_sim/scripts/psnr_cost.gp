# psnr_cost.gp - chart 3: PSNR against the reference image versus cost, one
# panel per filter, one series per scene.
# Data: psnr_cost.dat, blocks filter-major (3 filters x 6 scenes):
# cost psnr method.
if (!exists("datadir")) datadir = "build-bench-host"
if (!exists("outdir")) outdir = "docs/bench"
scenes = "floor floor_rolled cube tunnel small_tris quad_near"
filters = "point bilinear trilinear"
set terminal pngcairo size 1500,520 font ",10"
set output outdir."/psnr_cost.png"
set multiplot layout 1,3 title "fixel: PSNR vs reference (100 dB = identical) against cost"
set xlabel "instructions / covered pixel (Cortex-M4 -O2; host where missing)"
set ylabel "PSNR, dB"
set logscale x
set grid
set key bottom right font ",8"
f = datadir."/psnr_cost.dat"
do for [k=0:2] {
    set title word(filters, k+1) noenhanced
    plot for [i=0:5] f index (k*6+i) using 1:2 with points pt (i+4) ps 1.2 title word(scenes, i+1) noenhanced
}
unset multiplot
