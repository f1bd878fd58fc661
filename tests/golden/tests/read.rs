//! The golden files read whole, and a malformed file names the offending field.

#[test]
fn every_case_of_both_files_is_read() {
    let impact = carry_golden::impact_cases().expect("impact.json");
    let flight = carry_golden::flight_cases().expect("flight.json");
    assert_eq!(impact.len(), 26);
    assert_eq!(flight.len(), 21);
    // every impact case expects either a result or an error, never both
    for c in &impact {
        assert!(
            c.expected.is_some() != c.expected_error.is_some(),
            "{}",
            c.name
        );
    }
    // the bare NaN token of an error case is read as NaN
    assert!(impact.iter().any(|c| c.delivery.club_speed_mps.is_nan()));
    assert!(flight.iter().all(|c| c.expected.carry_m > 0.0));
}

#[test]
fn the_embedded_files_are_the_files_on_disk() {
    let dir = carry_golden::dir();
    let on_disk = |n: &str| std::fs::read_to_string(dir.join(n)).expect("golden file on disk");
    assert_eq!(on_disk("impact.json"), carry_golden::IMPACT_JSON);
    assert_eq!(on_disk("flight.json"), carry_golden::FLIGHT_JSON);
}
