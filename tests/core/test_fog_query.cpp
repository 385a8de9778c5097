// Placeholder while the implementation is being written.
