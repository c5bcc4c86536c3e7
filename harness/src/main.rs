//! clipbench: the harness CLI.
fn main() {}
