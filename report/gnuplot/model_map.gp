# A model-based learner's map after a run's last trial (report/figures.h, ModelMapPicture;
# docs/learning.md "Inside the model"): its combinations with the best chance that a window holds,
# best on top, each with the median of a window's E and its band, and whether it was walked.
# Variables: map (rank, label, hold, e_deg, e_low_deg, e_high_deg, tried), title, subtitle
# ("the last episode's model after trial 12"), threshold (degrees), rows.
load dir.'common.gp'
set title title."\n".subtitle.": best chance to hold on top (P: that a window holds)" font ',12' noenhanced
set yrange [rows + 0.6:0.4]
set xrange [0:*]
set ytics scale 0 font ',10' noenhanced
set grid xtics noytics
set lmargin 40
set bmargin 6
set xlabel sprintf('E of a window (degrees): median and band (16–84 %%); dashed: the threshold, %g°', threshold)
set key outside bottom center horizontal box opaque font ',10'
set arrow 1 from threshold, graph 0 to threshold, graph 1 nohead lw 2 dt 2 lc rgb 'black'
tried(x) = column('tried') == x ? column('rank') : NaN
plot map using 'e_deg':(tried(1)):'e_low_deg':'e_high_deg' with xerrorbars pt 7 ps 1.3 lw 1.5 lc rgb green title 'walked', \
     map using 'e_deg':(tried(0)):'e_low_deg':'e_high_deg' with xerrorbars pt 6 ps 1.3 lw 1.5 lc rgb blue title 'not walked', \
     map using (0):'rank':ytic(sprintf('%s  P %.2f', strcol('label'), column('hold'))) with points ps 0 notitle
