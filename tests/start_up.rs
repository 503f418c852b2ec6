//! How the binary starts: where glibc is linked in statically
//! (`.cargo/config.toml` turns on `crt-static` for Linux), the binary is
//! also linked at a fixed address (build.rs), so that no start runs the
//! dynamic loader or relocates the binary (0.4 ms of the 0.9 that
//! `homerun --version` took). A change of build flags that loses either
//! fails here, not only in the timings.

/// Read from the ELF file's header and program headers (64-bit and little
/// endian, as every target this runs on is).
#[cfg(all(target_os = "linux", target_env = "gnu", target_feature = "crt-static"))]
#[test]
fn the_binary_is_linked_statically_at_a_fixed_address() {
    let elf = std::fs::read(env!("CARGO_BIN_EXE_homerun")).unwrap();
    let u16_at = |at: usize| u16::from_le_bytes([elf[at], elf[at + 1]]);
    let u32_at = |at: usize| u32::from_le_bytes(elf[at..at + 4].try_into().unwrap());
    let u64_at = |at: usize| u64::from_le_bytes(elf[at..at + 8].try_into().unwrap());
    assert_eq!(&elf[..5], b"\x7fELF\x02", "a 64-bit ELF file");
    const EXECUTABLE: u16 = 2; // ET_EXEC; a position-independent one is ET_DYN (3)
    assert_eq!(u16_at(16), EXECUTABLE, "linked at a fixed address");
    let (first, size, count) = (u64_at(32) as usize, u16_at(54) as usize, u16_at(56));
    assert!(count > 0);
    const DYNAMIC: u32 = 2; // PT_DYNAMIC: libraries to load, relocations to do
    const INTERPRETER: u32 = 3; // PT_INTERP: the dynamic loader
    for header in 0..count as usize {
        let kind = u32_at(first + header * size);
        assert!(
            kind != DYNAMIC && kind != INTERPRETER,
            "program header {header} is of type {kind}: linked dynamically"
        );
    }
}

/// Losing the flag fails a test rather than compiling the one above away.
#[cfg(all(
    target_os = "linux",
    target_env = "gnu",
    not(target_feature = "crt-static")
))]
#[test]
fn the_binary_is_linked_statically_at_a_fixed_address() {
    panic!("built without crt-static: is .cargo/config.toml's [target] table read?");
}
