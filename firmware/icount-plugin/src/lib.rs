//! QEMU TCG plugin (plugin API v1, QEMU 7.2+): exact guest instruction counts between
//! marker functions.
//!
//! Every translated guest instruction gets an inline `counter += 1` (executed by the
//! generated host code, no callback), so the count is exact and deterministic — it does
//! not depend on host load. The first instruction of each marker function gets an exec
//! callback that snapshots the counter:
//!
//! * `carry_icount_start` — opens a region,
//! * `carry_icount_stop`  — closes it and prints `icount region <k> <instructions>`.
//!
//! Markers are found by symbol name (QEMU loads the ELF's symbol table with `-kernel`),
//! or by address with `-plugin libcarry_icount_plugin.so,start=0x..,stop=0x..`.
//! `out=PATH` writes the lines to PATH instead of stderr. At exit the plugin prints the
//! total instruction count of the run (`icount total <n>`).
//!
//! `profile=N` also counts per function symbol (a second inline counter per instruction)
//! and prints, after each region, its top N functions:
//! `icount region <k> fn <instructions> <demangled name>`. With LTO most of the core is
//! inlined into a few functions; the out-of-line ones (libm, soft-float, memcpy) show up
//! by name.
#![allow(clippy::missing_safety_doc)]

use qemu_plugin_sys::*;
use std::ffi::{CStr, c_char, c_int, c_uint, c_void};
use std::io::Write;
use std::sync::Mutex;

#[unsafe(no_mangle)]
pub static qemu_plugin_version: c_int = QEMU_PLUGIN_VERSION as c_int;

/// The instruction counter, bumped inline by translated code (single vCPU).
static mut COUNT: u64 = 0;

/// Per-symbol counters (profile mode), bumped inline like [`COUNT`].
const MAX_SYMBOLS: usize = 16384;
static mut SYM_COUNT: [u64; MAX_SYMBOLS] = [0; MAX_SYMBOLS];
/// Per-instruction counters (`addrs=K`: region K's counts by address), bumped inline.
const MAX_ADDRS: usize = 1 << 20;
static mut ADDR_COUNT: [u64; MAX_ADDRS] = [0; MAX_ADDRS];

struct State {
    profile: usize,
    addrs_region: Option<u64>,
    addr_slots: std::collections::BTreeMap<u64, usize>,
    addr_snapshot: Vec<u64>,
    symbols: Vec<String>,
    symbol_index: std::collections::BTreeMap<usize, usize>,
    snapshot: Vec<u64>,
    start_addr: Option<u64>,
    stop_addr: Option<u64>,
    opened: Option<u64>,
    region: u64,
    out: Option<std::fs::File>,
}

static STATE: Mutex<State> = Mutex::new(State {
    profile: 0,
    addrs_region: None,
    addr_slots: std::collections::BTreeMap::new(),
    addr_snapshot: Vec::new(),
    symbols: Vec::new(),
    symbol_index: std::collections::BTreeMap::new(),
    snapshot: Vec::new(),
    start_addr: None,
    stop_addr: None,
    opened: None,
    region: 0,
    out: None,
});

fn sym_counts(n: usize) -> Vec<u64> {
    // SAFETY: single vCPU; read while translated code is not running (inside a callback).
    (0..n)
        .map(|i| unsafe { core::ptr::read_volatile((&raw const SYM_COUNT).cast::<u64>().add(i)) })
        .collect()
}

fn addr_counts() -> Vec<u64> {
    // SAFETY: as `sym_counts`.
    (0..MAX_ADDRS)
        .map(|i| unsafe { core::ptr::read_volatile((&raw const ADDR_COUNT).cast::<u64>().add(i)) })
        .collect()
}

const START: usize = 1;
const STOP: usize = 2;

fn count() -> u64 {
    // SAFETY: single vCPU; the inline ops write it only while this callback is not running.
    unsafe { core::ptr::read_volatile(&raw const COUNT) }
}

fn emit(st: &mut State, line: &str) {
    match st.out.as_mut() {
        Some(f) => {
            let _ = writeln!(f, "{line}");
            let _ = f.flush();
        }
        None => eprintln!("{line}"),
    }
}

unsafe extern "C" fn on_marker(_vcpu: c_uint, udata: *mut c_void) {
    let now = count();
    let mut st = STATE.lock().unwrap();
    match udata as usize {
        START => {
            st.opened = Some(now);
            if st.profile > 0 {
                st.snapshot = sym_counts(st.symbols.len());
            }
            if st.addrs_region == Some(st.region) {
                st.addr_snapshot = addr_counts();
            }
        }
        STOP => {
            if let Some(t0) = st.opened.take() {
                let k = st.region;
                st.region += 1;
                emit(&mut st, &format!("icount region {k} {}", now - t0));
                if st.addrs_region == Some(k) {
                    let after = addr_counts();
                    let lines: Vec<String> = st
                        .addr_slots
                        .iter()
                        .filter_map(|(&a, &i)| {
                            let d = after[i] - st.addr_snapshot.get(i).copied().unwrap_or(0);
                            (d > 0).then(|| format!("icount addr {a:x} {d}"))
                        })
                        .collect();
                    for l in lines {
                        emit(&mut st, &l);
                    }
                }
                if st.profile > 0 {
                    let after = sym_counts(st.symbols.len());
                    let mut delta: Vec<(u64, usize)> = after
                        .iter()
                        .enumerate()
                        .map(|(i, &c)| (c - st.snapshot.get(i).copied().unwrap_or(0), i))
                        .filter(|&(d, _)| d > 0)
                        .collect();
                    delta.sort_unstable_by(|a, b| b.cmp(a));
                    delta.truncate(st.profile);
                    for (d, i) in delta {
                        let line = format!("icount region {k} fn {d} {}", st.symbols[i]);
                        emit(&mut st, &line);
                    }
                }
            }
        }
        _ => {}
    }
}

unsafe fn marker_kind(st: &State, insn: *const qemu_plugin_insn) -> usize {
    let vaddr = unsafe { qemu_plugin_insn_vaddr(insn) };
    if st.start_addr == Some(vaddr) {
        return START;
    }
    if st.stop_addr == Some(vaddr) {
        return STOP;
    }
    if st.start_addr.is_none() && st.stop_addr.is_none() {
        // By symbol: only the first instruction of the function is a marker.
        let sym = unsafe { qemu_plugin_insn_symbol(insn) };
        if !sym.is_null() {
            let name = unsafe { CStr::from_ptr(sym) }.to_bytes();
            if name == b"carry_icount_start" {
                return START;
            }
            if name == b"carry_icount_stop" {
                return STOP;
            }
        }
    }
    0
}

/// The counter slot of the function containing `insn` (profile mode).
fn symbol_slot(st: &mut State, sym: *const c_char) -> usize {
    let key = sym as usize;
    if let Some(&i) = st.symbol_index.get(&key) {
        return i;
    }
    let name = if sym.is_null() {
        "<no symbol>".to_owned()
    } else {
        let raw = unsafe { CStr::from_ptr(sym) }.to_string_lossy();
        format!("{:#}", rustc_demangle::demangle(&raw))
    };
    // Distinct pointers may name the same function: share its slot.
    let i = match st.symbols.iter().position(|s| *s == name) {
        Some(i) => i,
        None if st.symbols.len() < MAX_SYMBOLS - 1 => {
            st.symbols.push(name);
            st.symbols.len() - 1
        }
        None => MAX_SYMBOLS - 1,
    };
    st.symbol_index.insert(key, i);
    i
}

unsafe extern "C" fn on_tb_trans(_id: qemu_plugin_id_t, tb: *mut qemu_plugin_tb) {
    let n = unsafe { qemu_plugin_tb_n_insns(tb) };
    let mut st = STATE.lock().unwrap();
    let mut prev_sym: *const c_char = core::ptr::null();
    for i in 0..n {
        let insn = unsafe { qemu_plugin_tb_get_insn(tb, i) };
        unsafe {
            qemu_plugin_register_vcpu_insn_exec_inline(
                insn,
                qemu_plugin_op::QEMU_PLUGIN_INLINE_ADD_U64,
                (&raw mut COUNT).cast(),
                1,
            );
        }
        if st.profile > 0 {
            let slot = symbol_slot(&mut st, unsafe { qemu_plugin_insn_symbol(insn) });
            unsafe {
                qemu_plugin_register_vcpu_insn_exec_inline(
                    insn,
                    qemu_plugin_op::QEMU_PLUGIN_INLINE_ADD_U64,
                    (&raw mut SYM_COUNT).cast::<u64>().add(slot).cast(),
                    1,
                );
            }
        }
        if st.addrs_region.is_some() {
            let a = unsafe { qemu_plugin_insn_vaddr(insn) };
            let n = st.addr_slots.len();
            let slot = *st.addr_slots.entry(a).or_insert(n.min(MAX_ADDRS - 1));
            unsafe {
                qemu_plugin_register_vcpu_insn_exec_inline(
                    insn,
                    qemu_plugin_op::QEMU_PLUGIN_INLINE_ADD_U64,
                    (&raw mut ADDR_COUNT).cast::<u64>().add(slot).cast(),
                    1,
                );
            }
        }
        let kind = unsafe { marker_kind(&st, insn) };
        // A symbol lookup matches every instruction of the marker function: keep only the
        // one where the symbol starts (first in its TB, or a change of symbol).
        let sym = unsafe { qemu_plugin_insn_symbol(insn) };
        let first_of_symbol = i == 0 || sym != prev_sym;
        prev_sym = sym;
        if kind != 0 && (st.start_addr.is_some() || first_of_symbol) {
            unsafe {
                qemu_plugin_register_vcpu_insn_exec_cb(
                    insn,
                    Some(on_marker),
                    qemu_plugin_cb_flags::QEMU_PLUGIN_CB_NO_REGS,
                    kind as *mut c_void,
                );
            }
        }
    }
}

unsafe extern "C" fn on_exit(_id: qemu_plugin_id_t, _p: *mut c_void) {
    let total = count();
    let mut st = STATE.lock().unwrap();
    emit(&mut st, &format!("icount total {total}"));
}

fn parse_addr(v: &str) -> Option<u64> {
    let v = v.trim();
    match v.strip_prefix("0x") {
        Some(h) => u64::from_str_radix(h, 16).ok(),
        None => v.parse().ok(),
    }
    .map(|a| a & !1) // Thumb symbol addresses carry bit 0
}

#[unsafe(no_mangle)]
pub unsafe extern "C" fn qemu_plugin_install(
    id: qemu_plugin_id_t,
    _info: *const qemu_info_t,
    argc: c_int,
    argv: *mut *mut c_char,
) -> c_int {
    let mut st = STATE.lock().unwrap();
    for i in 0..argc as usize {
        let arg = unsafe { CStr::from_ptr(*argv.add(i)) }
            .to_string_lossy()
            .into_owned();
        let arg = arg.strip_prefix("arg=").unwrap_or(&arg).to_owned();
        let Some((k, v)) = arg.split_once('=') else {
            eprintln!("carry-icount: bad argument {arg:?}");
            return -1;
        };
        match k {
            "start" => st.start_addr = parse_addr(v),
            "stop" => st.stop_addr = parse_addr(v),
            "profile" => st.profile = v.parse().unwrap_or(0),
            "addrs" => st.addrs_region = v.parse().ok(),
            "out" => match std::fs::File::create(v) {
                Ok(f) => st.out = Some(f),
                Err(e) => {
                    eprintln!("carry-icount: {v}: {e}");
                    return -1;
                }
            },
            _ => {
                eprintln!("carry-icount: unknown argument {k:?}");
                return -1;
            }
        }
    }
    drop(st);
    unsafe {
        qemu_plugin_register_vcpu_tb_trans_cb(id, Some(on_tb_trans));
        qemu_plugin_register_atexit_cb(id, Some(on_exit), core::ptr::null_mut());
    }
    0
}
