set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_fibre_bounce_dt1e-05.svg'
set datafile separator ','
set title 'Relative energy error, fibre_bounce, dt = 1e-05 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_fibre_bounce_cayley_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'cayley', \
     '../series/energy_fibre_bounce_direct_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'direct', \
     '../series/energy_fibre_bounce_exact_splitting_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'exact_splitting', \
     '../series/energy_fibre_bounce_fincham_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'fincham', \
     '../series/energy_fibre_bounce_munjiza_rk4_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'munjiza_rk4', \
     '../series/energy_fibre_bounce_no_gyro_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'no_gyro', \
     '../series/energy_fibre_bounce_no_squish_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'no_squish', \
     '../series/energy_fibre_bounce_omelyan_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 1 title 'omelyan', \
     '../series/energy_fibre_bounce_richardson_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'richardson', \
     '../series/energy_fibre_bounce_rozmanov_kusalik_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'rozmanov_kusalik', \
     '../series/energy_fibre_bounce_spiral_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'spiral', \
     '../series/energy_fibre_bounce_zvw_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'zvw', \
     '../series/energy_fibre_bounce_zvw_corrected_dt1e-05.csv' using 1:2 with lines lw 1.5 dt 2 title 'zvw_corrected'
