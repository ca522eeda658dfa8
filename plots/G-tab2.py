#!/usr/bin/env python3
"""G-tab2: Gray et al. 2001 Table 2, plate periods against V_f for each mu, with the published values."""
import plate_plots
import plotstyle as ps

args = ps.parse_args(__doc__)
plate_plots.plot_table(args.results, args.figures, "G-tab2", 2)
