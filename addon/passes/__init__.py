"""GPU passes: surface, edge highlight, composite. Drawing only; nothing here classifies."""
