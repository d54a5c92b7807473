"""spindle: lumped thermal spindle model, its FMU and the co-simulation master (issue 4).

For now it holds the command line that runs the demo of the analytic bearing FMU.
"""
