set terminal svg size 800,450 dynamic noenhanced font 'sans,12'
set output 'energy_fibre_bounce_dt6.25e-07.svg'
set datafile separator ','
set title 'Relative energy error, fibre_bounce, dt = 6.25e-07 s'
set xlabel 't (s)'
set ylabel '(E - E0) / |E0|'
set key outside right
set grid
plot '../series/energy_fibre_bounce_direct_dt6.25e-07.csv' using 1:2 with lines lw 1.5 title 'direct', \
     '../series/energy_fibre_bounce_munjiza_rk4_dt6.25e-07.csv' using 1:2 with lines lw 1.5 title 'munjiza_rk4', \
     '../series/energy_fibre_bounce_zvw_dt6.25e-07.csv' using 1:2 with lines lw 1.5 title 'zvw', \
     '../series/energy_fibre_bounce_zvw_corrected_dt6.25e-07.csv' using 1:2 with lines lw 1.5 title 'zvw_corrected'
