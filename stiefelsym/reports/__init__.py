"""Renderers: results to terminal, Markdown, LaTeX, tables and notebook displays."""
