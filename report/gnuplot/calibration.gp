# The calibration of the body against Table 1 (docs/fidelity.md): Spearman's rank correlation of
# each searched body parameter (rows) with each number the candidates walked (columns), over the
# space-filling design. Red: the number grows with the parameter; blue: it falls. Deviations count
# + = left, so a blue cell under "R1" means the parameter turns the robot harder to the right.
# Variables: data (x, y, rho, parameter, number), title, subtitle, xtics_list and ytics_list
# (gnuplot tic lists "label" position, ...), nx, ny.
load dir.'common.gp'
set title title."\n{/*0.8 ".subtitle."}" font ',14'
set palette defined (-1 '#2166ac', -0.5 '#92c5de', 0 '#f7f7f7', 0.5 '#f4a582', 1 '#b2182b')
set cbrange [-1:1]
set cblabel "Spearman's rank correlation"
set xrange [-0.5:nx - 0.5]
set yrange [ny - 0.5:-0.5]
set grid noxtics noytics
set tics scale 0
set key off
eval('set xtics ('.xtics_list.') rotate by 30 right noenhanced')
eval('set ytics ('.ytics_list.') noenhanced')
set lmargin 22
set bmargin 7
plot data using 'x':'y':'rho' with image, \
     data using 'x':'y':(sprintf('%.2f', column('rho'))) with labels font ',10'
