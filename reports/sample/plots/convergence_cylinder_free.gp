set terminal svg size 1200,480 dynamic noenhanced font 'sans,12'
set logscale xy
set format x '%g'
set format y '%.0e'
set grid
set key outside right
names = 'cayley direct exact_splitting fincham munjiza_rk4 no_gyro no_squish omelyan richardson rozmanov_kusalik spiral zvw zvw_corrected'
titles = 'cayley(1.97x) direct(1.00x) exact_splitting(18.55x) fincham(0.95x) munjiza_rk4(1.51x) no_gyro(0.79x) no_squish(2.81x) omelyan(2.51x) richardson(1.35x) rozmanov_kusalik(2.26x) spiral(0.98x) zvw(1.19x) zvw_corrected(1.26x)'
file = 'runs_cylinder_free.dat'
set output 'convergence_cylinder_free.svg'
set title 'cylinder_free: omega_err_max against dt'
set xlabel 'dt (s)'
set ylabel 'omega_err_max'
e0 = 0.0006771156688254277; d0 = 0.0001; lo = 1e-06; hi = 0.01
slope(x, p) = (x >= lo && x <= hi) ? e0*(x/d0)**p : 1/0  # drawn over the data's dt only
set xrange [lo/1.5:hi*1.5]
set yrange [1.4357549069934104e-14/3:1.9996001199593216*3]
set samples 200
plot for [i=1:words(names)] file index (i-1) using 1:2 with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.6 title word(names, i), \
     slope(x, 1) dt 2 lc 'gray50' title 'slope 1', slope(x, 2) dt 3 lc 'gray30' title 'slope 2', \
     slope(x, 4) dt 4 lc 'gray10' title 'slope 4'
