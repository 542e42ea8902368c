"""Towed-cable dynamics: the 3-D implicit finite-difference box scheme of paper 000."""
