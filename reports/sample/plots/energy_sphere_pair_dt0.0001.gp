set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_sphere_pair_dt0.0001.svg'
set datafile separator ','
set title 'Relative energy error, sphere_pair, dt = 0.0001 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_sphere_pair_cayley_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'cayley', \
     '../series/energy_sphere_pair_direct_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'direct', \
     '../series/energy_sphere_pair_exact_splitting_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'exact_splitting', \
     '../series/energy_sphere_pair_fincham_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'fincham', \
     '../series/energy_sphere_pair_munjiza_rk4_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'munjiza_rk4', \
     '../series/energy_sphere_pair_no_gyro_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'no_gyro', \
     '../series/energy_sphere_pair_no_squish_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'no_squish', \
     '../series/energy_sphere_pair_omelyan_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 1 title 'omelyan', \
     '../series/energy_sphere_pair_richardson_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 2 title 'richardson', \
     '../series/energy_sphere_pair_rozmanov_kusalik_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 2 title 'rozmanov_kusalik', \
     '../series/energy_sphere_pair_spiral_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 2 title 'spiral', \
     '../series/energy_sphere_pair_zvw_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 2 title 'zvw', \
     '../series/energy_sphere_pair_zvw_corrected_dt0.0001.csv' using 1:2 with lines lw 1.5 dt 2 title 'zvw_corrected'
