MODULE FrameWeld
    ! generator: gen-rapid 0.1.0
    ! cell: frame-weld.yaml
    ! model: irb2600_12_165 (ABB IRB 2600-12/1.65, built into gen-rapid)
    ! urdf: irb2600_12_165.urdf
    ! controller: irb2600_12_165.controller.yaml
    ! coupling: serial (axes 1..6 = URDF joints 1..6)
    ! planner: extensile
    ! grid (deg): 1.000
    ! clearance (mm): 10.0
    ! base: [0.0, 0.0, 0.0] yaw: 0.000
    ! tool: tTorch2600 (declared below; collision shapes: mount, neck, nozzle)
    ! wobj: wobjFrame (declared below; robtargets are in its user frame)
    ! frames: robtargets and the user frame are given in the cell frame; they mean the cell's poses only if the controller's base frame is the base and yaw above
    ! moves: 10
    ! min clearance (mm): 10.3
    ! estimated time (s): 20.92
    ! zoned vias: 0 of 1 (via zone fine)
    ! the paper's method alone: 10 moves, 20.92 s

    PERS tooldata tTorch2600 := [TRUE,[[116.673,0.000,336.673],[0.923879539,0.000000000,0.382683416,0.000000000]],[4.500,[0.000,0.000,120.000],[1,0,0,0],0,0,0]];
    PERS wobjdata wobjFrame := [FALSE,TRUE,"",[[900.000,-400.000,880.000],[1.000000000,0.000000000,0.000000000,0.000000000]],[[0,0,0],[1,0,0,0]]];

    CONST jointtarget home := [[0.000,0.000,0.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget NL1 := [[-31.224,-28.579,33.804,69.972,32.205,-75.610],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NL1_rt := [[5.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget NL2 := [[-28.156,-23.135,30.429,71.944,28.647,-77.508],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NL2_rt := [[75.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget FL1 := [[-16.981,11.779,-1.520,72.278,17.227,-76.020],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FL1_rt := [[525.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget FL2 := [[-15.974,17.423,-8.403,67.512,16.720,-70.861],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FL2_rt := [[595.000,80.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[-1,0,-1,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget via05_01 := [[3.000,7.000,-16.000,89.315,-1.687,-88.819],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget FR1 := [[16.981,11.779,-1.520,107.722,-17.227,-103.980],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FR1_rt := [[525.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget FR2 := [[15.974,17.423,-8.403,112.488,-16.720,-109.139],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget FR2_rt := [[595.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget NR1 := [[31.224,-28.579,33.804,110.028,-32.205,-104.390],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NR1_rt := [[5.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget NR2 := [[28.156,-23.135,30.429,108.056,-28.647,-102.492],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget NR2_rt := [[75.000,720.000,0.000],[0.258819010,0.000000000,0.965925836,0.000000000],[0,1,-2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home2 := [[0.000,0.000,0.000,0.000,45.000,0.000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ NL1\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ NL2\NoEOffs, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ FL1\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ FL2\NoEOffs, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ via05_01\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ FR1\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ FR2\NoEOffs, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ NR1\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ NR2\NoEOffs, v20, fine, tTorch2600\WObj:=wobjFrame;
        MoveAbsJ home2\NoEOffs, v500, fine, tTorch2600\WObj:=wobjFrame;
    ENDPROC
ENDMODULE
