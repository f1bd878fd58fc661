//! Puts the workspace root's `memory.x` on the linker search path (cortex-m-rt's `link.x`
//! INCLUDEs it) and links with `link.x`, so the image needs no rustflags.
use std::path::PathBuf;

fn main() {
    let manifest = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let out = PathBuf::from(std::env::var_os("OUT_DIR").unwrap_or_default());
    let layout = manifest.join("../memory.x");
    if let Err(e) = std::fs::copy(&layout, out.join("memory.x")) {
        println!("cargo:warning=cannot copy {}: {e}", layout.display());
        std::process::exit(1);
    }
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rustc-link-arg-bins=-Tlink.x");
    println!("cargo:rustc-link-arg-bins=--nmagic");
    println!("cargo:rerun-if-changed={}", layout.display());
    println!("cargo:rerun-if-changed=build.rs");
}
