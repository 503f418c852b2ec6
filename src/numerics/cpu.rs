//! Whether the CPU runs AVX2, asked once per process, with two CPUID
//! instructions where std's `is_x86_feature_detected!` asks eight: in a
//! virtual machine each traps to the hypervisor (~4 µs on this project's
//! machine), and the first flight of a command waits on the answer (std's
//! took 31 µs of a 3 ms surface).

use std::sync::atomic::{AtomicU8, Ordering};

/// 0: not asked yet; 1: no; 2: yes.
static AVX2: AtomicU8 = AtomicU8::new(0);

/// Whether this CPU, and the OS, run AVX2 instructions.
#[inline]
pub fn has_avx2() -> bool {
    match AVX2.load(Ordering::Relaxed) {
        0 => {
            let has = detect_avx2();
            AVX2.store(if has { 2 } else { 1 }, Ordering::Relaxed);
            has
        }
        known => known == 2,
    }
}

/// CPUID leaf 1: AVX, and OSXSAVE (the OS saves extended registers, so
/// XGETBV may be asked which); XCR0: the OS saves the YMM registers (and
/// the XMM ones); leaf 7: AVX2. A CPU with AVX has leaf 7 (it has leaf
/// 0xD, which AVX needs).
#[cfg(target_arch = "x86_64")]
#[cold]
fn detect_avx2() -> bool {
    use std::arch::x86_64::{__cpuid, __cpuid_count};
    const OSXSAVE: u32 = 1 << 27;
    const AVX: u32 = 1 << 28;
    const AVX2: u32 = 1 << 5;
    let leaf1 = __cpuid(1);
    if leaf1.ecx & (OSXSAVE | AVX) != OSXSAVE | AVX {
        return false;
    }
    // SAFETY: OSXSAVE says the CPU has XGETBV and the OS enabled it.
    let saved = unsafe { extended_registers_saved() };
    saved && __cpuid_count(7, 0).ebx & AVX2 != 0
}

/// Whether the OS saves the XMM and YMM registers (XCR0 bits 1 and 2).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "xsave")]
fn extended_registers_saved() -> bool {
    const XMM_YMM: u64 = 0b110;
    // SAFETY: compiled for XSAVE, whose XGETBV this is.
    let xcr0 = unsafe { std::arch::x86_64::_xgetbv(0) };
    xcr0 & XMM_YMM == XMM_YMM
}

#[cfg(not(target_arch = "x86_64"))]
fn detect_avx2() -> bool {
    false
}

#[cfg(test)]
mod tests {
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn avx2_is_found_where_std_finds_it() {
        assert_eq!(
            super::has_avx2(),
            std::arch::is_x86_feature_detected!("avx2")
        );
        // Asked again: the cached answer.
        assert_eq!(super::has_avx2(), super::detect_avx2());
    }
}
