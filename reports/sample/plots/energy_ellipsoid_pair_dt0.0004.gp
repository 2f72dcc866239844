set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_ellipsoid_pair_dt0.0004.svg'
set datafile separator ','
set title 'Relative energy error, ellipsoid_pair, dt = 0.0004 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_ellipsoid_pair_direct_dt0.0004.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_ellipsoid_pair_munjiza_rk4_dt0.0004.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_ellipsoid_pair_zvw_dt0.0004.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_ellipsoid_pair_zvw_corrected_dt0.0004.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
