//! Integer linear systems by Cramer's rule over many primes (multimodular elimination), for the
//! large systems where fraction-free elimination spends its time multiplying and dividing huge
//! minors.
//!
//! For an integer system A X = B, the integers `det A` and `Y = adj(A) B = det(A) · X` are
//! computed modulo primes p just below 2^62 (Gaussian elimination mod p, in Montgomery form) and
//! put together by the Chinese remainder theorem (Garner's mixed radix). Hadamard's bound
//! `|minor| ≤ Π_i ‖row_i of [A | B]‖₂` bounds every one of them, so once the product of the
//! primes exceeds twice the bound the symmetric residues are the integers themselves: the result
//! is exact, not probable. A prime dividing det A is skipped; a matrix singular modulo several
//! primes in a row is reported as (probably) singular with `None`, and the caller then takes
//! its exact path.

use crate::exact::IntMatrix;
use cagd_scalar::BigInt;
use num_bigint::{BigUint, Sign};
use num_integer::Integer;
use num_traits::{Signed, Zero};
use std::sync::Mutex;

/// Arithmetic modulo an odd prime p < 2^62 in Montgomery form (R = 2^64).
#[derive(Clone, Copy, Debug)]
struct Mont {
    p: u64,
    /// −p⁻¹ mod 2^64.
    pinv: u64,
    /// R² mod p.
    r2: u64,
    /// R mod p = 2^64 mod p, for folding 128-bit sums.
    r1: u64,
}

impl Mont {
    fn new(p: u64) -> Self {
        let mut inv = p;
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
        }
        let r = ((1u128 << 64) % u128::from(p)) as u64;
        let r2 = ((u128::from(r) * u128::from(r)) % u128::from(p)) as u64;
        Mont {
            p,
            pinv: inv.wrapping_neg(),
            r2,
            r1: r,
        }
    }

    /// t R⁻¹ mod p, for t < p · 2^64.
    #[inline]
    fn redc(&self, t: u128) -> u64 {
        let m = (t as u64).wrapping_mul(self.pinv);
        let u = ((t + u128::from(m) * u128::from(self.p)) >> 64) as u64;
        if u >= self.p {
            u - self.p
        } else {
            u
        }
    }

    /// A 128-bit value congruent to t modulo p: t = h 2^64 + l ≡ h (2^64 mod p) + l, below
    /// (p + 1) 2^64; folded twice, below p² + p + 2^64 < p 2^64, ready for [`Mont::redc`].
    #[inline]
    fn fold(&self, t: u128) -> u128 {
        (t >> 64) * u128::from(self.r1) + u128::from(t as u64)
    }

    #[inline]
    fn mul(&self, a: u64, b: u64) -> u64 {
        self.redc(u128::from(a) * u128::from(b))
    }

    #[inline]
    fn add(&self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p {
            s - self.p
        } else {
            s
        }
    }

    #[inline]
    fn sub(&self, a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + self.p - b
        }
    }

    /// x R mod p, for any 64-bit x (x · R² < p · 2^64, so one reduction suffices).
    fn enter(&self, x: u64) -> u64 {
        self.redc(u128::from(x) * u128::from(self.r2))
    }

    fn leave(&self, x: u64) -> u64 {
        self.redc(u128::from(x))
    }

    /// x^e in Montgomery form.
    fn pow(&self, x: u64, mut e: u64) -> u64 {
        let mut acc = self.enter(1);
        let mut base = x;
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, base);
            }
            base = self.mul(base, base);
            e >>= 1;
        }
        acc
    }

    /// The Montgomery form of the integer with these little-endian limbs and sign.
    fn reduce(&self, limbs: &[u64], negative: bool) -> u64 {
        // Horner in base 2^64, in Montgomery form: (x 2^64 + d) R = redc(x R · R²) + d R
        // (no division)
        let mut x = 0u64;
        for &d in limbs.iter().rev() {
            x = self.add(self.mul(x, self.r2), self.enter(d));
        }
        if negative {
            self.sub(0, x)
        } else {
            x
        }
    }
}

fn mul_mod(a: u64, b: u64, p: u64) -> u64 {
    ((u128::from(a) * u128::from(b)) % u128::from(p)) as u64
}

fn pow_mod(mut a: u64, mut e: u64, p: u64) -> u64 {
    let mut acc = 1u64;
    while e > 0 {
        if e & 1 == 1 {
            acc = mul_mod(acc, a, p);
        }
        a = mul_mod(a, a, p);
        e >>= 1;
    }
    acc
}

/// Deterministic Miller–Rabin for 64-bit integers.
fn is_prime(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for &b in &BASES {
        if n % b == 0 {
            return n == b;
        }
    }
    let (mut d, mut s) = (n - 1, 0);
    while d % 2 == 0 {
        d /= 2;
        s += 1;
    }
    'bases: for &a in &BASES {
        let mut x = pow_mod(a, d, n);
        if x == 1 || x == n - 1 {
            continue;
        }
        for _ in 1..s {
            x = mul_mod(x, x, n);
            if x == n - 1 {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// The primes just below 2^62, in decreasing order, computed once per process.
static PRIMES: Mutex<Vec<u64>> = Mutex::new(Vec::new());

/// The primes number `from..to` below 2^62, counting down from 2^62 (decreasing).
fn primes(from: usize, to: usize) -> Vec<u64> {
    let mut cache = match PRIMES.lock() {
        Ok(guard) => guard,
        Err(poisoned) => poisoned.into_inner(),
    };
    let mut candidate = cache.last().map_or((1u64 << 62) - 1, |&p| p - 2);
    while cache.len() < to {
        if is_prime(candidate) {
            cache.push(candidate);
        }
        candidate -= 2;
    }
    cache.iter().take(to).skip(from).copied().collect()
}

/// An integer as sign and little-endian limbs.
fn limbs(x: &BigInt) -> (bool, Vec<u64>) {
    let (sign, digits) = x.to_u64_digits();
    (sign == Sign::Minus, digits)
}

/// `det A mod p` and `X = A⁻¹ B mod p` (row by row, plain residues), or `None` when A is
/// singular modulo p.
///
/// Row by row (Doolittle's order): row i of `[A | B]` is reduced by the rows of U above it,
/// with every update `x_j −= l_k u_kj` added, unreduced, to a 128-bit accumulator (as
/// `l_k (p − u_kj)`) and folded only every third step: one 64-bit product per update instead
/// of a product and a Montgomery reduction. An entry is reduced when it becomes a multiplier
/// or the row is done. A row whose pivot vanishes modulo p is set aside for the next one
/// (partial pivoting), and the determinant changes sign.
fn solve_mod(
    mont: &Mont,
    entries: &[(bool, Vec<u64>)],
    n: usize,
    r: usize,
) -> Option<(u64, Vec<u64>)> {
    let w = n + r;
    let a: Vec<u64> = entries
        .iter()
        .map(|(neg, l)| mont.reduce(l, *neg))
        .collect();
    let one = mont.enter(1);
    // the rows of U (w entries each; the first i of row i are not used) and 1/u_ii
    let mut u: Vec<u64> = Vec::with_capacity(n * w);
    let mut inverses: Vec<u64> = Vec::with_capacity(n);
    let mut det = one;
    // the rows of A not placed yet, in their order
    let mut waiting: Vec<&[u64]> = a.chunks_exact(w.max(1)).collect();
    let mut acc = vec![0u128; w];
    let mut row = vec![0u64; w];
    for i in 0..n {
        cagd_scalar::cancel::checkpoint();
        let mut placed = None;
        for (pos, original) in waiting.iter().enumerate() {
            reduce_row(mont, original, &u, &inverses, w, &mut acc, &mut row);
            if row.get(i).is_some_and(|&x| x != 0) {
                placed = Some(pos);
                break;
            }
        }
        let pos = placed?;
        // moving row `pos` of the waiting ones up to place i swaps it past `pos` rows, each
        // swap a sign: the same as the swaps of partial pivoting
        if pos % 2 == 1 {
            det = mont.sub(0, det);
        }
        waiting.remove(pos);
        let pivot = *row.get(i)?;
        det = mont.mul(det, pivot);
        inverses.push(mont.pow(pivot, mont.p - 2));
        u.extend_from_slice(&row);
    }
    // back substitution for every right-hand side at once, from the last row up: the rows
    // x_{n-1}, x_{n-2}, ... (r entries each) of X, then Y = det · X
    let mut y_rev: Vec<u64> = Vec::with_capacity(n * r);
    if r > 0 {
        for (i, (row, &inv)) in u.chunks_exact(w).zip(&inverses).enumerate().rev() {
            let (coefs, rhs) = row.split_at_checked(n)?;
            let upper = coefs.get(i + 1..)?;
            let start = y_rev.len();
            y_rev.extend_from_slice(rhs);
            let (solved, acc) = y_rev.split_at_mut(start);
            // `solved` holds x_{n-1}, ..., x_{i+1}: reversed, the x_j for j = i+1.. in order
            for (&a_ij, x_j) in upper.iter().zip(solved.chunks_exact(r).rev()) {
                for (s, &x_jc) in acc.iter_mut().zip(x_j) {
                    *s = mont.sub(*s, mont.mul(a_ij, x_jc));
                }
            }
            for s in acc.iter_mut() {
                *s = mont.mul(*s, inv);
            }
        }
    }
    let y: Vec<u64> = y_rev
        .chunks_exact(r.max(1))
        .rev()
        .flatten()
        .copied()
        .collect();
    let plain: Vec<u64> = y.iter().map(|&x| mont.leave(x)).collect();
    Some((mont.leave(det), plain))
}

/// `original` (a row of `[A | B]`, Montgomery form) reduced by the rows of U so far, into
/// `row`: x = a − Σ_k l_k u_k with l_k = x_k / u_kk, the entries of the columns of U zero.
fn reduce_row(
    mont: &Mont,
    original: &[u64],
    u: &[u64],
    inverses: &[u64],
    w: usize,
    acc: &mut [u128],
    row: &mut [u64],
) {
    let one = u128::from(mont.enter(1));
    // a_j R · R = a_j R², the scale of a product of two Montgomery forms
    for (s, &x) in acc.iter_mut().zip(original) {
        *s = u128::from(x) * one;
    }
    let mut pending = 0;
    for (k, (u_k, &inv)) in u.chunks_exact(w.max(1)).zip(inverses).enumerate() {
        let Some((x_k, rest)) = acc.get_mut(k..).and_then(|a| a.split_first_mut()) else {
            break;
        };
        let x = mont.redc(mont.fold(mont.fold(*x_k)));
        if x == 0 {
            continue;
        }
        let l = u128::from(mont.mul(x, inv));
        for (s, &u_kj) in rest.iter_mut().zip(u_k.iter().skip(k + 1)) {
            // < 2^124: at most three of them on top of a folded value (< 2^126)
            *s += l * u128::from(mont.p - u_kj);
        }
        pending += 1;
        if pending == 3 {
            for s in rest.iter_mut() {
                *s = mont.fold(*s);
            }
            pending = 0;
        }
    }
    for (x, &s) in row.iter_mut().zip(acc.iter()) {
        *x = mont.redc(mont.fold(mont.fold(s)));
    }
}

/// The integers with these residues modulo the primes, in the symmetric range (Garner).
struct Crt {
    primes: Vec<u64>,
    monts: Vec<Mont>,
    /// `steps[j][i]` = p_i · R mod p_j (i < j), for Horner with one reduction per step.
    steps: Vec<Vec<u64>>,
    /// (p_0 ⋯ p_{j−1})⁻¹ · R mod p_j.
    inverses: Vec<u64>,
    product: BigUint,
}

impl Crt {
    fn new(primes: Vec<u64>) -> Self {
        let monts: Vec<Mont> = primes.iter().map(|&p| Mont::new(p)).collect();
        let mut steps = Vec::with_capacity(primes.len());
        let mut inverses = Vec::with_capacity(primes.len());
        for (j, mont) in monts.iter().enumerate() {
            let row: Vec<u64> = primes.iter().take(j).map(|&pi| mont.enter(pi)).collect();
            let prod = row.iter().fold(mont.enter(1), |acc, &x| mont.mul(acc, x));
            inverses.push(mont.pow(prod, mont.p - 2));
            steps.push(row);
        }
        let product = primes.iter().fold(BigUint::from(1u8), |acc, &p| acc * p);
        Crt {
            primes,
            monts,
            steps,
            inverses,
            product,
        }
    }

    /// The integer with residue `residues[j]` modulo p_j (one residue per prime).
    fn combine(&self, residues: &[u64]) -> BigInt {
        // the mixed-radix digits v_0, v_1, ...: x = v_0 + p_0 (v_1 + p_1 (v_2 + ...))
        let mut v: Vec<u64> = Vec::with_capacity(self.primes.len());
        let per_prime = self
            .monts
            .iter()
            .zip(&self.steps)
            .zip(&self.inverses)
            .zip(residues);
        for (((mont, steps), &inverse), &residue) in per_prime {
            // t = v_0 + p_0 (v_1 + p_1 (v_2 + ...)) mod p_j, plain, from the digits so far
            let mut t = 0u64;
            for (&v_i, &step) in v.iter().zip(steps).rev() {
                // v_i < p_i < 2^62 < 2 p_j
                let vi = if v_i >= mont.p { v_i - mont.p } else { v_i };
                t = mont.add(mont.redc(u128::from(t) * u128::from(step)), vi);
            }
            let diff = mont.sub(residue, t);
            v.push(mont.redc(u128::from(diff) * u128::from(inverse)));
        }
        let mut x = BigUint::zero();
        for (&v_j, &p_j) in v.iter().zip(&self.primes).rev() {
            x *= p_j;
            x += v_j;
        }
        if &x + &x > self.product {
            BigInt::from_biguint(Sign::Minus, &self.product - x)
        } else {
            BigInt::from_biguint(Sign::Plus, x)
        }
    }
}

thread_local! {
    /// Whether the work of this thread stays on it (see [`on_this_thread`]).
    static ON_THIS_THREAD: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f` with the multimodular work it starts on the calling thread alone, not spread over
/// the cores: for a caller that already keeps every core busy (a batch solved on `--threads`),
/// where more threads would only contend with its own.
pub fn on_this_thread<T>(f: impl FnOnce() -> T) -> T {
    let before = ON_THIS_THREAD.with(|c| c.replace(true));
    let out = f();
    ON_THIS_THREAD.with(|c| c.set(before));
    out
}

/// `items.iter().map(f)` on all cores (scoped threads, contiguous chunks, results in order);
/// `None` if a thread failed. Inside [`on_this_thread`], on the calling thread only.
fn parallel_map<T: Sync, U: Send>(items: &[T], f: impl Fn(&T) -> U + Sync) -> Option<Vec<U>> {
    // asked once per process: the standard library reads the cgroup's quota at every call
    static THREADS: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    let threads = *THREADS
        .get_or_init(|| std::thread::available_parallelism().map_or(1, std::num::NonZero::get));
    if threads < 2 || items.len() < 2 || ON_THIS_THREAD.with(std::cell::Cell::get) {
        return Some(items.iter().map(f).collect());
    }
    let chunk = items.len().div_ceil(threads);
    let f = &f;
    std::thread::scope(|scope| {
        let handles: Vec<_> = items
            .chunks(chunk)
            .map(|part| scope.spawn(move || part.iter().map(f).collect::<Vec<U>>()))
            .collect();
        let parts = handles
            .into_iter()
            .map(|h| h.join().ok())
            .collect::<Option<Vec<Vec<U>>>>()?;
        Some(parts.into_iter().flatten().collect())
    })
}

/// Bits of Hadamard's bound on every n × n minor of `[A | B]`, plus two.
pub(crate) fn hadamard_bits(a: &IntMatrix, b: &IntMatrix) -> u64 {
    let n = a.rows();
    let w = (n + b.cols()) as f64;
    let mut bits = 2.0;
    for i in 0..n {
        let row_max = (0..n)
            .map(|j| a.get(i, j).bits())
            .chain((0..b.cols()).map(|j| b.get(i, j).bits()))
            .max()
            .unwrap_or(0);
        bits += row_max as f64 + 0.5 * w.log2();
    }
    bits.ceil() as u64
}

/// `(Y, det A)` with `A Y = det(A) · B` by multimodular Cramer; `None` when A looks singular
/// (singular modulo the first primes tried).
pub(crate) fn solve_multimodular(a: &IntMatrix, b: &IntMatrix) -> Option<(IntMatrix, BigInt)> {
    let n = a.rows();
    let r = b.cols();
    let bound = hadamard_bits(a, b);
    let entries: Vec<(bool, Vec<u64>)> = (0..n)
        .flat_map(|i| {
            (0..n)
                .map(move |j| a.get(i, j))
                .chain((0..r).map(move |j| b.get(i, j)))
        })
        .map(|x| limbs(&x))
        .collect();
    let needed = usize::try_from(bound / 61 + 2).ok()?;
    let mut used: Vec<u64> = Vec::with_capacity(needed);
    let mut results: Vec<(u64, Vec<u64>)> = Vec::with_capacity(needed);
    let mut failures = 0;
    let mut next = 0;
    // a first prime alone (a singular matrix is found at once), then up to each checkpoint,
    // where the solution is tried by rational reconstruction (exact once verified)
    let mut checkpoint = 1;
    while 61 * used.len() as u64 <= bound {
        cagd_scalar::cancel::checkpoint();
        let batch = checkpoint.min(needed).saturating_sub(used.len()).max(1);
        let pool = primes(next, next + batch);
        let solved = parallel_map(&pool, |&p| {
            solve_mod(&Mont::new(p), &entries, n, r).map(|res| (p, res))
        })?;
        next += batch;
        for res in solved {
            match res {
                Some((p, res)) => {
                    used.push(p);
                    results.push(res);
                }
                None => failures += 1,
            }
        }
        if used.is_empty() && failures >= 3 {
            return None;
        }
        if used.len() >= checkpoint && 61 * (used.len() as u64) <= bound {
            if used.len() >= 4 {
                if let Some(solution) = reconstruct(a, b, &used, &results) {
                    return Some(solution);
                }
            }
            checkpoint += (checkpoint / 2).max(2);
        }
    }
    // Cramer's rule: det A and Y = det(A) X, both below the bound
    let crt = Crt::new(used.clone());
    let det = crt.combine(&results.iter().map(|(d, _)| *d).collect::<Vec<_>>());
    if det.is_zero() {
        return None;
    }
    let entries: Vec<Option<BigInt>> = parallel_map(&(0..n * r).collect::<Vec<_>>(), |&k| {
        // every residue vector has n · r entries
        let mut residues: Vec<u64> = Vec::with_capacity(results.len());
        for ((d, x), &p) in results.iter().zip(&used) {
            residues.push(mul_mod(*x.get(k)?, *d, p));
        }
        Some(crt.combine(&residues))
    })?;
    let mut y: Vec<BigInt> = Vec::with_capacity(n * r);
    for entry in entries {
        y.push(entry?);
    }
    Some((IntMatrix::from_big(n, r, y), det))
}

/// The solution X = Y / d from its residues modulo the primes so far, by rational
/// reconstruction with one common denominator, **verified** exactly (`A Y = d B`); `None` when
/// the primes do not suffice yet.
fn reconstruct(
    a: &IntMatrix,
    b: &IntMatrix,
    primes: &[u64],
    results: &[(u64, Vec<u64>)],
) -> Option<(IntMatrix, BigInt)> {
    let (n, r) = (a.rows(), b.cols());
    let crt = Crt::new(primes.to_vec());
    let modulus = BigInt::from(crt.product.clone());
    // numerators and denominators up to √(P/2): then n/d is unique
    let half = BigInt::from((&crt.product >> 1u8).sqrt());
    let mut den = BigInt::from(1u8);
    let mut nums: Vec<BigInt> = Vec::with_capacity(n * r);
    let mut residues: Vec<u64> = Vec::with_capacity(results.len());
    for k in 0..n * r {
        residues.clear();
        for (_, x) in results {
            residues.push(*x.get(k)?);
        }
        let x = crt.combine(&residues);
        // den · x in the symmetric range
        let mut v = (x * &den) % &modulus;
        if v.is_negative() {
            v += &modulus;
        }
        if &v + &v > modulus {
            v -= &modulus;
        }
        if v.magnitude() <= half.magnitude() {
            nums.push(v);
            continue;
        }
        let (num, d) = rational_reconstruction(&v, &modulus, &half)?;
        for prev in &mut nums {
            *prev *= &d;
        }
        den *= d;
        if den > half {
            return None;
        }
        nums.push(num);
    }
    let y = IntMatrix::from_big(n, r, nums);
    let ay = a.mul(&y);
    let exact = (0..n).all(|i| (0..r).all(|c| ay.get(i, c) == b.get(i, c) * &den));
    exact.then_some((y, den))
}

/// The fraction n/d (d > 0, |n| and d at most `bound`) congruent to `v` modulo `m`, by the
/// half-extended Euclidean algorithm (Wang's rational reconstruction); `None` if there is none.
fn rational_reconstruction(v: &BigInt, m: &BigInt, bound: &BigInt) -> Option<(BigInt, BigInt)> {
    let mut v = v % m;
    if v.is_negative() {
        v += m;
    }
    let (mut r0, mut r1) = (m.clone(), v);
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::from(1u8));
    while r1.magnitude() > bound.magnitude() {
        let (q, rem) = r0.div_rem(&r1);
        r0 = std::mem::replace(&mut r1, rem);
        let t = &t0 - &q * &t1;
        t0 = std::mem::replace(&mut t1, t);
    }
    if t1.is_zero() || t1.magnitude() > bound.magnitude() {
        return None;
    }
    if t1.is_negative() {
        Some((-r1, -t1))
    } else {
        Some((r1, t1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn montgomery_arithmetic_and_primes() {
        let p = primes(0, 3);
        assert!(p.iter().all(|&q| is_prime(q) && q < 1 << 62 && q > 1 << 61));
        assert!(p[0] > p[1] && p[1] > p[2]);
        assert!(is_prime(1_000_000_007) && !is_prime(1_000_000_007 * 3));
        let m = Mont::new(p[0]);
        let (a, b) = (123_456_789_u64, 987_654_321_u64);
        let prod = m.leave(m.mul(m.enter(a), m.enter(b)));
        assert_eq!(prod, mul_mod(a, b, p[0]));
        let inv = m.pow(m.enter(a), p[0] - 2);
        assert_eq!(m.leave(m.mul(inv, m.enter(a))), 1);
        // a big integer reduced limb by limb
        let x = BigInt::from(3u8).pow(200) * -1;
        let (neg, l) = limbs(&x);
        let expected = (&x % BigInt::from(p[0]) + BigInt::from(p[0])) % BigInt::from(p[0]);
        assert_eq!(BigInt::from(m.leave(m.reduce(&l, neg))), expected);
    }

    #[test]
    fn crt_recovers_signed_integers() {
        let crt = Crt::new(primes(0, 6)); // more than 2^366: enough for 7^90 ≈ 2^253
        for x in [
            BigInt::from(-5),
            BigInt::from(3u8).pow(150),
            -BigInt::from(7u8).pow(90),
        ] {
            let residues: Vec<u64> = crt
                .primes
                .iter()
                .map(|&p| {
                    let r = ((&x % BigInt::from(p)) + BigInt::from(p)) % BigInt::from(p);
                    u64::try_from(&r).unwrap()
                })
                .collect();
            assert_eq!(crt.combine(&residues), x);
        }
    }

    #[test]
    fn zero_pivots_are_passed_over_and_the_determinant_keeps_its_sign() {
        // leading entries zero: rows 1 and 2 come up past row 0, as partial pivoting would
        let a = IntMatrix::from_i128(3, 3, vec![0, 2, 1, 0, 0, 5, 3, 0, 0]);
        let b = IntMatrix::from_i128(3, 1, vec![1, 2, 3]);
        // [A | b] row by row, as solve_multimodular hands it over
        let rows: Vec<(bool, Vec<u64>)> = (0..3)
            .flat_map(|i| (0..3).map(move |j| (i, j)))
            .map(|(i, j)| limbs(&a.get(i, j)))
            .collect::<Vec<_>>()
            .chunks(3)
            .zip(0..3)
            .flat_map(|(row, i)| row.iter().cloned().chain([limbs(&b.get(i, 0))]))
            .collect();
        for p in primes(0, 3) {
            let mont = Mont::new(p);
            let (det, x) = solve_mod(&mont, &rows, 3, 1).unwrap();
            // det A = 0·(0·0 - 5·0) - 2·(0·0 - 5·3) + 1·(0·0 - 0·3) = 30
            assert_eq!(det, 30);
            // A x = b modulo p
            for i in 0..3 {
                let ax = (0..3).fold(0u64, |acc, j| {
                    let aij = u64::try_from(a.get(i, j)).unwrap();
                    (acc + mul_mod(aij, x[j], p)) % p
                });
                assert_eq!(ax, u64::try_from(b.get(i, 0)).unwrap());
            }
        }
        let (y, det) = solve_multimodular(&a, &b).unwrap();
        let (y2, det2) = crate::bareiss::solve_bareiss(&a, &b).unwrap();
        for i in 0..3 {
            assert_eq!(y.get(i, 0) * &det2, y2.get(i, 0) * &det);
        }
    }

    #[test]
    fn agrees_with_fraction_free_elimination() {
        // a 6 × 6 integer system with big entries and two right-hand sides
        let big = |k: i64| BigInt::from(k) * BigInt::from(10u8).pow(30) + BigInt::from(k * k - 7);
        let a = IntMatrix::from_big(
            6,
            6,
            (0..36)
                .map(|k| big((k * 7 + 3) % 11 - 5 + i64::from(k % 7 == 0) * 9))
                .collect(),
        );
        let b = IntMatrix::from_big(6, 2, (0..12).map(|k| big(k - 4)).collect());
        let (y, det) = solve_multimodular(&a, &b).unwrap();
        let (y2, det2) = crate::bareiss::solve_bareiss(&a, &b).unwrap();
        // the same rationals Y/det (the fraction-free determinant may differ in sign)
        for i in 0..6 {
            for c in 0..2 {
                assert_eq!(y.get(i, c) * &det2, y2.get(i, c) * &det);
            }
        }
        let singular = IntMatrix::from_i128(2, 2, vec![1, 2, 2, 4]);
        assert!(solve_multimodular(&singular, &IntMatrix::from_i128(2, 1, vec![1, 1])).is_none());
        // a big matrix with a small solution: found by rational reconstruction long before
        // Hadamard's bound, and verified
        let x = IntMatrix::from_i128(6, 2, vec![3, -1, 0, 7, -5, 2, 1, 1, 9, -4, 2, 0]);
        let bx = a.mul(&x);
        let (y, d) = solve_multimodular(&a, &bx).unwrap();
        for i in 0..6 {
            for c in 0..2 {
                assert_eq!(y.get(i, c), x.get(i, c) * &d);
            }
        }
        assert!(
            d.bits() < 64,
            "the small common denominator, not det A: {d}"
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

        /// Small integer systems full of zeros (so zero pivots are frequent): the same
        /// solution as fraction-free elimination, and both see a singular matrix alike.
        #[test]
        fn small_systems_agree_with_fraction_free_elimination(
            n in 1usize..7,
            entries in proptest::collection::vec(-2i128..=2, 49),
            rhs in proptest::collection::vec(-5i128..=5, 14),
        ) {
            let a = IntMatrix::from_i128(n, n, entries[..n * n].to_vec());
            let b = IntMatrix::from_i128(n, 2, rhs[..n * 2].to_vec());
            let modular = solve_multimodular(&a, &b);
            let bareiss = crate::bareiss::solve_bareiss(&a, &b);
            match (modular, bareiss) {
                (Some((y, det)), Some((y2, det2))) => {
                    for i in 0..n {
                        for c in 0..2 {
                            proptest::prop_assert_eq!(y.get(i, c) * &det2, y2.get(i, c) * &det);
                        }
                    }
                }
                (None, None) => {}
                (m, f) => proptest::prop_assert!(
                    false,
                    "multimodular {:?}, fraction-free {:?}",
                    m.is_some(),
                    f.is_some()
                ),
            }
        }
    }
}
