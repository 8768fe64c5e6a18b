// Placeholder: tests pending.
