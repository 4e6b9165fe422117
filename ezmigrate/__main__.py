"""``python -m ezmigrate`` works like the ``ezmigrate`` command."""

from .cli import main

if __name__ == "__main__":
    main()
