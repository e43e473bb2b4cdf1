"""``python -m impactlab`` runs the command line."""

from impactlab.cli import main

main()
