"""leadscrew-selector: pick a leadscrew and nut against every published limit."""

__version__ = "0.1.0"
