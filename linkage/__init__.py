"""Planar crank mechanisms: kinematics and kinetostatics by Assur groups."""
