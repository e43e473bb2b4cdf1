"""A drop's contact and dent records show one short line in display units with their units
(the cells of the drop's contact table), not a dump of SI floats."""

from __future__ import annotations

from impactlab.dynamics.drop_records import ContactRecord, DentRecord

_CONTACT = ContactRecord(
    end=0, start=0.0, duration=0.0003309551993353525, delta_max=3.5243846158870295e-05,
    max_force=1468.9072069798594, normal_impulse=0.16847043317019042,
    tangential_impulse=0.033692645232009426, sliding_length=-0.000155514196644704,
    slip_path=0.000155514196644704, x_start=0.0, x_end=-0.0001168168909090057, dent=0,
    reload=False, delta_r=2.8035089808993045e-05, work_normal=-0.018628823454438868,
    work_friction=-0.017469312199353344, stick_time=2.0488537709065224e-06,
)  # fmt: skip

_DENT = DentRecord(
    end=0, x_min=-0.000261330703613744, x_max=1.5586386418354974e-08,
    contact_radius=0.0008009396251318825, delta_max=4.076204860762082e-05,
    delta_p=3.246889172265201e-05, unloading_radius=0.25189526097196585,
    max_force=1756.2533455454968, n_contacts=4,
)  # fmt: skip


def test_contact_record_repr_in_display_units() -> None:
    text = repr(_CONTACT)
    assert text == (
        "ContactRecord(end 0, start 0 ms, duration 0.33096 ms, delta_max 35.244 um, "
        "max_force 1468.9 N, normal_impulse 0.16847 N s, tangential_impulse 0.033693 N s, "
        "sliding_length -155.51 um, reload False)"
    )
    assert len(text) < 220 and "array(" not in text and "0.000330955" not in text


def test_dent_record_repr_in_display_units() -> None:
    text = repr(_DENT)
    assert text.startswith("DentRecord(end 0, x_min -261.33 um, x_max 0.015586 um, ")
    assert "delta_p 32.469 um" in text and "max_force 1756.3 N" in text
    assert text.endswith("n_contacts 4)") and len(text) < 200


def test_records_keep_fields_and_equality() -> None:
    same = ContactRecord.from_dict(_CONTACT.to_dict())
    assert same == _CONTACT and same.delta_max == 3.5243846158870295e-05
    assert DentRecord(**_DENT.__dict__) == _DENT
