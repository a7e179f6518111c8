from stiefelsym import claim, Lax   # Lax does not exist
