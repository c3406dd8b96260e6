set terminal pngcairo size 900,600 noenhanced
set output 'reports/compare_couette/comparison.png'
set title 'error vs wall time: couette'
set xlabel 'wall time [s]'
set ylabel 'final e_rms'
set logscale x
set logscale y
set grid
set key below
set offsets graph 0.02, graph 0.02, graph 0.05, graph 0.05
plot 'reports/compare_couette/comparison.dat' index 0 with linespoints title 'leapfrog_kdk', 'reports/compare_couette/comparison.dat' index 1 with linespoints title 'cvode_adams', 0.01 with lines dt 2 lc rgb 'gray40' title 'error 0.01', 0.001 with lines dt 2 lc rgb 'gray40' title 'error 0.001'
