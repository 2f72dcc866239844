set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_ellipsoid_pair_dt2.5e-05.svg'
set datafile separator ','
set title 'Relative energy error, ellipsoid_pair, dt = 2.5e-05 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_ellipsoid_pair_cayley_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'cayley', \
     '../series/energy_ellipsoid_pair_direct_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'direct', \
     '../series/energy_ellipsoid_pair_exact_splitting_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'exact_splitting', \
     '../series/energy_ellipsoid_pair_fincham_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'fincham', \
     '../series/energy_ellipsoid_pair_munjiza_rk4_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'munjiza_rk4', \
     '../series/energy_ellipsoid_pair_no_gyro_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'no_gyro', \
     '../series/energy_ellipsoid_pair_no_squish_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'no_squish', \
     '../series/energy_ellipsoid_pair_omelyan_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'omelyan', \
     '../series/energy_ellipsoid_pair_richardson_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'richardson', \
     '../series/energy_ellipsoid_pair_rozmanov_kusalik_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'rozmanov_kusalik', \
     '../series/energy_ellipsoid_pair_spiral_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'spiral', \
     '../series/energy_ellipsoid_pair_zvw_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'zvw', \
     '../series/energy_ellipsoid_pair_zvw_corrected_dt2.5e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'zvw_corrected'
