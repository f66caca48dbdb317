# Fig. 8 (paper §4.1): the deviation E of every trial of one learning run; accepted
# trials move the combination, the grey steps show E_ref (the accepted combination's deviation)
# and learning stops below the threshold E_req. Short runs get each trial's period change
# written above its point.
# Variables: data (trial, deviation_deg, accepted, reference_deg, change, one period column per
# leg), threshold (degrees).
load dir.'common.gp'
max_labelled_trials = 30
stats data using 'trial' nooutput
last_trial = STATS_max
labelled = last_trial <= max_labelled_trials
if (labelled) { set xtics 1 }
set xrange [-0.5:last_trial + 0.5]
set yrange [0:*]
set offsets 0, 0, graph 0.1, 0
set xlabel 'trial (0 = detection window, all periods 4)'
set ylabel 'deviation E per trial (degrees)'
set title 'Learning trace of one run' font ',14'
set key outside right top vertical font ',10'
plot threshold with lines lw 2 dt 2 lc rgb 'black' title sprintf('threshold E_{req} = %g°', threshold), \
     data using 'trial':'reference_deg' with steps lw 2 lc rgb grey title 'E_{ref} (accepted combination)', \
     data using 'trial':(column('accepted') == 1 ? column('deviation_deg') : NaN) with points pt 7 ps 1.4 lc rgb green title 'accepted', \
     data using 'trial':(column('accepted') == 0 ? column('deviation_deg') : NaN) with points pt 2 ps 1.6 lw 2 lc rgb red title 'rejected', \
     data using 'trial':(labelled ? column('deviation_deg') : NaN):'change' with labels offset 0, 1.1 font ',9' notitle
