//! The budget's own tests: caps, deadlines, interrupts and the units.

use super::*;

#[test]
fn an_interrupt_from_another_thread_stops_the_check() {
    let b = Budget::new();
    let _on = b.enter();
    assert_eq!(check(), Ok(()));
    let h = b.interrupt_handle();
    std::thread::spawn(move || h.interrupt()).join().unwrap();
    assert_eq!(check(), Err(Stop::Interrupted));
    assert!(stopped());
    b.interrupt_handle().clear();
    assert_eq!(check(), Ok(()));
}

#[test]
fn a_deadline_passes() {
    let b = Budget::new().with_timeout(Duration::from_millis(1));
    let _on = b.enter();
    std::thread::sleep(Duration::from_millis(3));
    assert_eq!(check(), Err(Stop::Timeout(Duration::from_millis(1))));
    assert!(
        check()
            .unwrap_err()
            .to_string()
            .contains("more than 1 ms (--timeout)")
    );
}

#[test]
fn the_budget_before_is_restored() {
    let outer = Budget::new();
    let _o = outer.enter();
    {
        let inner = Budget::preview();
        let _i = inner.enter();
        inner.interrupt_handle().interrupt();
        assert!(stopped());
        assert!(room(PREVIEW_NUMBERS + 1).is_err());
    }
    assert!(!stopped());
    assert!(room(PREVIEW_NUMBERS + 1).is_ok());
}

#[test]
fn the_statement_cap_names_the_size_it_would_have_taken() {
    let b = Budget::new();
    let _on = b.enter();
    begin_statement(0);
    hold(STATEMENT_NUMBERS - 10).unwrap();
    let e = hold(4_000_000).unwrap_err();
    assert_eq!(
        e,
        Stop::Memory {
            wanted: STATEMENT_NUMBERS + 3_999_990,
            cap: STATEMENT_NUMBERS,
            limit: Limit::Statement,
            base: 0,
        }
    );
    let e = e.wanting(1_200_000_000);
    assert_eq!(
        e.to_string(),
        "this would hold 1,200,000,000 numbers (9.6 GB); one statement may hold at most 50,000,000 numbers (400 MB)"
    );
    // Nothing was counted by the refusal; a finished list is released.
    assert_eq!(held(), STATEMENT_NUMBERS - 10);
    release_to(0);
    assert_eq!(held(), 0);
}

#[test]
fn the_run_cap_counts_the_bindings() {
    let b = Budget::new().with_max_memory(8_000);
    let _on = b.enter();
    begin_statement(900);
    assert!(room(100).is_ok());
    let e = room(101).unwrap_err();
    assert_eq!(
        e.to_string(),
        "this would hold 1,001 numbers (8 kB); --max-memory allows at most 1,000 numbers (8 kB)"
    );
}

#[test]
fn sizes_and_seconds_parse() {
    assert_eq!(parse_size("512M"), Ok(512_000_000));
    assert_eq!(parse_size("2G"), Ok(2_000_000_000));
    assert_eq!(parse_size("1.5GB"), Ok(1_500_000_000));
    assert_eq!(parse_size("1GiB"), Ok(1 << 30));
    assert_eq!(parse_size("100000"), Ok(100_000));
    assert!(parse_size("lots").is_err());
    assert!(parse_size("2X").is_err());
    assert!(parse_size("0").is_err());
    assert_eq!(parse_seconds("0.5"), Ok(Duration::from_millis(500)));
    assert!(parse_seconds("-1").is_err());
    assert!(parse_seconds("inf").is_err());
    assert_eq!(count(1_200_000_000), "1,200,000,000");
    assert_eq!(count(999), "999");
    assert_eq!(bytes(9_600_000_000), "9.6 GB");
    assert_eq!(bytes(400_000_000), "400 MB");
}
