"""``python -m stiefelsym``: the command line."""
from stiefelsym.cli import main

if __name__ == "__main__":
    main(prog_name="stiefelsym")
