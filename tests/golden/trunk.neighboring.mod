MODULE TrunkWeld
    ! generator: gen-rapid 0.1.0
    ! cell: trunk.yaml
    ! urdf: irb1400.urdf
    ! controller: irb1400.controller.yaml
    ! coupling: parallelogram (axis 3 = URDF joint 3 + joint 2)
    ! planner: neighboring
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, -850.0, 0.0] yaw: 90.000
    ! moves: 65
    ! min clearance (mm): 10.0
    ! estimated time (s): 16.61
    ! zoned vias: 0 of 60 (via zone fine)
    ! the paper's method alone: 65 moves, 16.61 s

    CONST jointtarget A := [[90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_01 := [[74.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_02 := [[72.000,0.000,-2.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_03 := [[71.000,-1.000,-3.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_04 := [[70.000,-1.000,-4.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_05 := [[69.000,0.000,-5.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_06 := [[68.000,0.000,-6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_07 := [[67.000,0.000,-6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_08 := [[66.000,0.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_09 := [[63.000,0.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_10 := [[62.000,0.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_11 := [[59.000,0.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_12 := [[58.000,-1.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_13 := [[57.000,0.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_14 := [[54.000,0.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_15 := [[52.000,-2.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_16 := [[51.000,-3.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_17 := [[48.000,0.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_18 := [[46.000,0.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_19 := [[44.000,2.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_20 := [[39.000,7.000,-2.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_21 := [[39.000,9.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_22 := [[39.000,10.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_23 := [[38.000,11.000,1.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via01_24 := [[38.000,12.000,2.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget B := [[30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget C := [[25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_01 := [[13.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_02 := [[9.000,15.000,6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_03 := [[8.000,14.000,6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_04 := [[7.000,15.000,5.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_05 := [[-7.000,15.000,5.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_06 := [[-8.000,14.000,6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_07 := [[-9.000,15.000,6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via03_08 := [[-13.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget D := [[-25.000,15.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget E := [[-30.000,20.000,10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[-30.000,20.000,6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_02 := [[-31.000,20.000,5.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_03 := [[-42.000,9.000,-6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_04 := [[-43.000,9.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_05 := [[-46.000,12.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_06 := [[-47.000,13.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_07 := [[-48.000,12.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_08 := [[-49.000,12.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_09 := [[-50.000,11.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_10 := [[-51.000,11.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_11 := [[-52.000,10.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_12 := [[-53.000,10.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_13 := [[-54.000,9.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_14 := [[-55.000,9.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_15 := [[-56.000,8.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_16 := [[-60.000,8.000,-10.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_17 := [[-61.000,7.000,-9.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_18 := [[-62.000,7.000,-9.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_19 := [[-63.000,6.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_20 := [[-64.000,5.000,-8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_21 := [[-65.000,4.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_22 := [[-66.000,3.000,-7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_23 := [[-67.000,2.000,-6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_24 := [[-68.000,1.000,-6.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_25 := [[-70.000,-1.000,-4.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_26 := [[-71.000,-1.000,-3.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_27 := [[-81.000,9.000,7.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_28 := [[-82.000,8.000,8.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget F := [[-90.000,0.000,0.000,0.000,30.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ A\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_04\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_05\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_06\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_07\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_08\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_09\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_10\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_11\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_12\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_13\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_14\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_15\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_16\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_17\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_18\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_19\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_20\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_21\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_22\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_23\NoEOffs, v300, fine, tool0;
        MoveAbsJ via01_24\NoEOffs, v300, fine, tool0;
        MoveAbsJ B\NoEOffs, v300, fine, tool0;
        MoveAbsJ C\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_04\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_05\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_06\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_07\NoEOffs, v300, fine, tool0;
        MoveAbsJ via03_08\NoEOffs, v300, fine, tool0;
        MoveAbsJ D\NoEOffs, v300, fine, tool0;
        MoveAbsJ E\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_01\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_02\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_03\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_04\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_05\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_06\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_07\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_08\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_09\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_10\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_11\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_12\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_13\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_14\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_15\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_16\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_17\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_18\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_19\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_20\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_21\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_22\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_23\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_24\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_25\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_26\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_27\NoEOffs, v300, fine, tool0;
        MoveAbsJ via05_28\NoEOffs, v300, fine, tool0;
        MoveAbsJ F\NoEOffs, v300, fine, tool0;
    ENDPROC
ENDMODULE
