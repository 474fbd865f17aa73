//! Rendering of diagnostics (text with carets, JSON).
