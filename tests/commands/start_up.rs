//! How the binary is built: rustc's default, position-independent (ELF
//! type DYN: PIE), as issue 25 asks, so that the loader places it at a
//! random address. A build that links it statically at a fixed address
//! (as one did, for 0.7 ms a process) fails here.

#[cfg(target_os = "linux")]
#[test]
fn the_binary_is_position_independent() {
    let elf = std::fs::read(env!("CARGO_BIN_EXE_homerun")).unwrap();
    assert_eq!(&elf[..4], b"\x7fELF", "an ELF file");
    const DYNAMIC: u16 = 3; // ET_DYN: a PIE; a fixed-address executable is ET_EXEC (2)
    assert_eq!(u16::from_le_bytes([elf[16], elf[17]]), DYNAMIC, "not a PIE");
}
