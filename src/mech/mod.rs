//! Mechanisms (chapter 2): joints, Grübler's formula, C-space topology.
