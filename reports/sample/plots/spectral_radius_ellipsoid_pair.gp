set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'spectral_radius_ellipsoid_pair.svg'
set title 'ellipsoid_pair (undamped): spectral radius of the step map'
set xlabel 'dt (s)'
set ylabel 'rho - 1'
set logscale xy
set format y '%.0e'
set grid
set key outside right
set yrange [1e-10:*]
names = 'cayley direct exact_splitting fincham munjiza_rk4 no_gyro no_squish omelyan richardson rozmanov_kusalik spiral zvw zvw_corrected'
file = 'spectral_radius_ellipsoid_pair.dat'
set arrow from 0.0007089815403622064,graph 0 to 0.0007089815403622064,graph 1 nohead dt 2 lc 'black'
set label 'Peng' at 0.0007089815403622064,graph 0.95 offset 0.5,0
plot for [i=1:words(names)] file index (i-1) using 1:($2-1) with linespoints pt (7 - 2*((i-1)/8)) dt 1+(i-1)/8 ps 0.5 title word(names, i)
