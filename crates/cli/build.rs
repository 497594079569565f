//! Links `cagd` as a position-dependent executable on Linux: a position-independent one has
//! thousands of relative relocations (8,421) that the dynamic loader applies at every start,
//! about a third of the instructions of `cagd solve` on an empty batch.

fn main() {
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let env = std::env::var("CARGO_CFG_TARGET_ENV").unwrap_or_default();
    if os == "linux" && env == "gnu" {
        println!("cargo:rustc-link-arg-bins=-no-pie");
    }
}
