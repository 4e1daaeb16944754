//! The explorer page's entry points in WebAssembly (`wasm32-unknown-unknown`, built by
//! `.ci/wasm` into `src/explorer/engine.wasm`): thin `extern "C"` wrappers around
//! [`crate::explore`], which holds the logic and the layout of the answers
//! ([`explore::answer_explore`], [`explore::answer_map`]) and is tested natively.
//!
//! The ABI, all numbers little-endian wasm32 (`usize` and pointers are 32 bits):
//!
//! ```text
//! alloc(len) -> ptr           a buffer of len bytes for the request (JSON, UTF-8)
//! free(ptr, len)              gives it back
//! explore(ptr, len) -> status the request of explore::Request; 0 = done, 1 = refused
//! map(ptr, len) -> status     the request of explore::MapRequest; 0 = done, 1 = refused
//! text_ptr(), text_len()      the text out (UTF-8) of the last call:
//!                               explore: the evaluation (guide §14) JSON, a NUL byte, the extras JSON
//!                               map:     the map's axes and legend (explore::MapInfo, JSON)
//!                               refused: the one-line error message
//! data_ptr(), data_len()      the numbers out (f64) of the last call:
//!                               explore: explore::Explored::curves
//!                               map:     the cells' categories, row by row from the bottom
//! ```
//!
//! The outputs live until the next call. Nothing here panics on any input: a bad request, an
//! invalid parameter or a failed integration is a refusal with its message.

use std::cell::RefCell;

use crate::explore::{self, Answer};

thread_local! {
    /// The text and numbers of the last call (wasm32 without threads has one thread).
    static OUT: RefCell<(Vec<u8>, Vec<f64>)> = const { RefCell::new((Vec::new(), Vec::new())) };
}

/// A buffer of `len` bytes that the caller fills and gives back with [`free`].
#[no_mangle]
pub extern "C" fn alloc(len: usize) -> *mut u8 {
    let mut buf = Vec::<u8>::with_capacity(len);
    let ptr = buf.as_mut_ptr();
    std::mem::forget(buf);
    ptr
}

/// Gives back a buffer of [`alloc`].
///
/// # Safety
/// `ptr` and `len` must come from one call of [`alloc`], and the buffer must not be used after.
#[no_mangle]
pub unsafe extern "C" fn free(ptr: *mut u8, len: usize) {
    // SAFETY: the caller passes a buffer of `alloc(len)`, whose capacity is `len`.
    drop(unsafe { Vec::from_raw_parts(ptr, 0, len) });
}

/// Evaluates, describes and samples the parameter set of the request at `ptr` (`len` bytes).
///
/// # Safety
/// `ptr` must point to `len` initialised bytes (a buffer of [`alloc`]).
#[no_mangle]
pub unsafe extern "C" fn explore(ptr: *const u8, len: usize) -> u32 {
    // SAFETY: the caller passes `len` initialised bytes at `ptr`.
    store(explore::answer_explore(unsafe {
        std::slice::from_raw_parts(ptr, len)
    }))
}

/// Computes the rows of a regime map asked for by the request at `ptr` (`len` bytes).
///
/// # Safety
/// `ptr` must point to `len` initialised bytes (a buffer of [`alloc`]).
#[no_mangle]
pub unsafe extern "C" fn map(ptr: *const u8, len: usize) -> u32 {
    // SAFETY: the caller passes `len` initialised bytes at `ptr`.
    store(explore::answer_map(unsafe {
        std::slice::from_raw_parts(ptr, len)
    }))
}

/// Keeps the outputs of a call for the page to read; returns its status.
fn store(answer: Answer) -> u32 {
    OUT.with(|o| *o.borrow_mut() = (answer.text, answer.data));
    answer.status
}

/// The text out of the last call.
#[no_mangle]
pub extern "C" fn text_ptr() -> *const u8 {
    OUT.with(|o| o.borrow().0.as_ptr())
}

/// Its length in bytes.
#[no_mangle]
pub extern "C" fn text_len() -> usize {
    OUT.with(|o| o.borrow().0.len())
}

/// The numbers out of the last call.
#[no_mangle]
pub extern "C" fn data_ptr() -> *const f64 {
    OUT.with(|o| o.borrow().1.as_ptr())
}

/// Their count.
#[no_mangle]
pub extern "C" fn data_len() -> usize {
    OUT.with(|o| o.borrow().1.len())
}
