set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_ellipsoid_pair_dt2.5e-05.svg'
set datafile separator ','
set title 'Relative energy error, ellipsoid_pair, dt = 2.5e-05 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_ellipsoid_pair_direct_dt2.5e-05.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_ellipsoid_pair_munjiza_rk4_dt2.5e-05.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_ellipsoid_pair_zvw_dt2.5e-05.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_ellipsoid_pair_zvw_corrected_dt2.5e-05.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
