<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>QObject</name>
    <message>
        <source>the demo has no differences file (its statistics come from check points)</source>
        <translation>演示数据没有差值文件（其统计量来自检查点）</translation>
    </message>
    <message>
        <source>Advanced (every other parameter)</source>
        <translation>高级（其余全部参数）</translation>
    </message>
    <message>
        <source>&lt;i&gt;none&lt;/i&gt;</source>
        <translation>&lt;i&gt;无&lt;/i&gt;</translation>
    </message>
    <message>
        <source>simulated</source>
        <translation>模拟</translation>
    </message>
    <message>
        <source>time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>time (UTC date)</source>
        <translation>时间（UTC 日期）</translation>
    </message>
    <message>
        <source>…</source>
        <translation>…</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>无法读取</translation>
    </message>
    <message>
        <source> ✎</source>
        <translation> ✎</translation>
    </message>
    <message>
        <source>Month (UTC)</source>
        <translation>月份（UTC）</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>accept</source>
        <translation>接受</translation>
    </message>
    <message>
        <source>reject</source>
        <translation>剔除</translation>
    </message>
    <message>
        <source>mark doubtful</source>
        <translation>标为存疑</translation>
    </message>
    <message>
        <source>automatic verdict for %1</source>
        <translation>%1 的自动判定</translation>
    </message>
    <message>
        <source>note on %1</source>
        <translation>%1 的备注</translation>
    </message>
    <message>
        <source>&lt;p&gt;Shows the shots for which the expression holds, with the verdict choice beside it (Alt+I). For example &lt;code&gt;snr &amp;lt; 10 and beam == 2&lt;/code&gt;, &lt;code&gt;verdict == &quot;doubtful&quot; or note != &quot;&quot;&lt;/code&gt;, &lt;code&gt;abs(dx) &amp;gt; 0.5&lt;/code&gt;, &lt;code&gt;not (roi == 1)&lt;/code&gt;.&lt;/p&gt;&lt;p&gt;&amp;lt; &amp;lt;= &amp;gt; &amp;gt;= == !=, and / or / not, ( ), numbers, &quot;text&quot;, + - * /, abs() and sqrt(). Names and text compare without regard to case. A missing number (a rejected shot&apos;s x) makes every comparison with it false.&lt;/p&gt;&lt;p&gt;Columns (&lt;i&gt;text&lt;/i&gt;): %1.&lt;/p&gt;&lt;p&gt;dx, dy: the centre less the nominal centre (the ROI&apos;s middle when none is given); verdict: as shown (manual where set); computed: the pipeline&apos;s; manual: 1 or 0; roi: the ROI&apos;s index in its frame.&lt;/p&gt;</source>
        <translation>&lt;p&gt;显示使表达式成立、且符合旁边判定选项的影像（Alt+I）。例如 &lt;code&gt;snr &amp;lt; 10 and beam == 2&lt;/code&gt;、&lt;code&gt;verdict == &quot;doubtful&quot; or note != &quot;&quot;&lt;/code&gt;、&lt;code&gt;abs(dx) &amp;gt; 0.5&lt;/code&gt;、&lt;code&gt;not (roi == 1)&lt;/code&gt;。&lt;/p&gt;&lt;p&gt;&amp;lt; &amp;lt;= &amp;gt; &amp;gt;= == !=、and / or / not、( )、数字、&quot;文本&quot;、+ - * /、abs() 和 sqrt()。名称和文本比较时不区分大小写。缺失的数值（如被剔除影像的 x）与任何值比较的结果均为假。&lt;/p&gt;&lt;p&gt;列（&lt;i&gt;文本&lt;/i&gt;）：%1。&lt;/p&gt;&lt;p&gt;dx、dy：中心减去标称中心（未给出标称中心时取 ROI 的中点）；verdict：显示的判定（设置了人工判定时取人工判定）；computed：流程计算的判定；manual：1 或 0；roi：ROI 在其帧中的序号。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>修改 %1</translation>
    </message>
    <message>
        <source>date unknown</source>
        <translation>日期未知</translation>
    </message>
    <message>
        <source>%1UTC on %2 (hh:mm:ss)</source>
        <translation>%1%2 UTC 时间（hh:mm:ss）</translation>
    </message>
    <message>
        <source>%1seconds of day, UTC %2 (s)</source>
        <translation>%1UTC %2 的日内秒（s）</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>unknown plot format &quot;%1&quot; (use .png, .svg or .pdf)</source>
        <translation>未知的绘图格式“%1”（请使用 .png、.svg 或 .pdf）</translation>
    </message>
    <message>
        <source>cannot render the plot as PNG</source>
        <translation>无法将绘图渲染为 PNG</translation>
    </message>
    <message>
        <source>Laser Workbench plot</source>
        <translation>激光工作台绘图</translation>
    </message>
    <message>
        <source>cannot start the SVG painter</source>
        <translation>无法启动 SVG 绘制器</translation>
    </message>
    <message>
        <source>Laser Workbench</source>
        <translation>激光工作台</translation>
    </message>
    <message>
        <source>cannot start the PDF painter</source>
        <translation>无法启动 PDF 绘制器</translation>
    </message>
    <message>
        <source>Plot size</source>
        <translation>绘图尺寸</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> pt</source>
        <translation> pt</translation>
    </message>
    <message>
        <source>As shown (%1 × %2)</source>
        <translation>与显示一致（%1 × %2）</translation>
    </message>
    <message>
        <source>Layout width</source>
        <translation>版面宽度</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>宽度</translation>
    </message>
    <message>
        <source>Layout height</source>
        <translation>版面高度</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>高度</translation>
    </message>
    <message>
        <source> dpi</source>
        <translation> dpi</translation>
    </message>
    <message>
        <source>Pixels per inch of the image: the layout above is drawn at dpi / 96 pixels per pixel (96: as on screen; 300: print)</source>
        <translation>图像每英寸的像素数：上方版面按每像素 dpi / 96 个像素绘制（96：与屏幕相同；300：印刷）</translation>
    </message>
    <message>
        <source>Writes %1 × %2 pixels (%3 × %4 cm at %5 dpi): the layout drawn at %6×</source>
        <translation>输出 %1 × %2 像素（%5 dpi 下为 %3 × %4 cm）：版面按 %6× 绘制</translation>
    </message>
    <message>
        <source>Writes a page of %1 × %2 points (%3 × %4 cm)</source>
        <translation>输出 %1 × %2 点的页面（%3 × %4 cm）</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>分辨率</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>未应用：%1</translation>
    </message>
    <message>
        <source>unknown key &quot;%1&quot; in the %2 session state</source>
        <translation>%2 会话状态中的未知键“%1”</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>SLR parameters</source>
        <translation>SLR 参数</translation>
    </message>
    <message>
        <source>out of memory: the run needs more memory than this process may take</source>
        <translation>内存不足：本次运行需要的内存超出本进程可用的内存</translation>
    </message>
    <message>
        <source>internal error: %1</source>
        <translation>内部错误：%1</translation>
    </message>
</context>
<context>
    <name>lwb::ui::BlinkView</name>
    <message numerus="yes">
        <source>Blink / tile: %n shots</source>
        <translation>
            <numerusform>闪烁比对 / 平铺：%n 幅影像</numerusform>
        </translation>
    </message>
    <message>
        <source>Tile</source>
        <translation>平铺</translation>
    </message>
    <message>
        <source>Blink</source>
        <translation>闪烁比对</translation>
    </message>
    <message>
        <source>Tile: every shot in a grid (T) · Blink: one at a time, cycled at the interval (B)</source>
        <translation>平铺：所有影像排成网格（T）· 闪烁比对：逐幅显示，按间隔循环（B）</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Time each shot is shown when blinking</source>
        <translation>闪烁比对时每幅影像的显示时间</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Start or stop the blinking (Space); ← / → step by hand</source>
        <translation>开始或停止闪烁比对（空格键）；← / → 手动逐幅切换</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>显示：</translation>
    </message>
    <message>
        <source>Every</source>
        <translation>全部</translation>
    </message>
    <message>
        <source>%1 / %2: %3</source>
        <translation>%1 / %2：%3</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
</context>
<context>
    <name>lwb::ui::CalibController</name>
    <message>
        <source>%1: %2 detectors</source>
        <translation>%1：%2 个探测器</translation>
    </message>
    <message>
        <source>%1: no beam designs (put beams.json beside the control points, or choose one)</source>
        <translation>%1：没有波束设计值（请将 beams.json 放在控制点文件旁，或另行选择）</translation>
    </message>
    <message>
        <source>%1: %2 control points, %3 beams</source>
        <translation>%1：%2 个控制点，%3 个波束</translation>
    </message>
    <message>
        <source>%1: %2 group(s) of differences</source>
        <translation>%1：%2 组差值</translation>
    </message>
</context>
<context>
    <name>lwb::ui::CalibParamsPanel</name>
    <message>
        <source>Detector surface fit (paper 002 §3.2.3)</source>
        <translation>探测器曲面拟合（文献 002 §3.2.3）</translation>
    </message>
    <message>
        <source>Surface</source>
        <translation>曲面</translation>
    </message>
    <message>
        <source>Auto (elliptical from 10 measured detectors)</source>
        <translation>自动（≥10 个探测器有测值时用椭圆）</translation>
    </message>
    <message>
        <source>Elliptical (7 parameters)</source>
        <translation>椭圆（7 个参数）</translation>
    </message>
    <message>
        <source>Circular (5 parameters)</source>
        <translation>圆（5 个参数）</translation>
    </message>
    <message>
        <source>Fit the background</source>
        <translation>拟合背景</translation>
    </message>
    <message>
        <source>Fixed background</source>
        <translation>固定背景</translation>
    </message>
    <message>
        <source>Trigger threshold</source>
        <translation>触发阈值</translation>
    </message>
    <message>
        <source>Saturation level</source>
        <translation>饱和值</translation>
    </message>
    <message>
        <source>Noise</source>
        <translation>噪声</translation>
    </message>
    <message>
        <source>Estimated from the array</source>
        <translation>由阵列估计</translation>
    </message>
    <message>
        <source>Given below</source>
        <translation>使用下方设定</translation>
    </message>
    <message>
        <source>Relative noise</source>
        <translation>相对噪声</translation>
    </message>
    <message>
        <source>Noise floor</source>
        <translation>噪声下限</translation>
    </message>
    <message>
        <source>Scale the covariance by χ²/dof</source>
        <translation>按 χ²/自由度缩放协方差</translation>
    </message>
    <message>
        <source>Pointing &amp;&amp; range calibration (eq. 2–5)</source>
        <translation>指向&amp;&amp;测距定标（式 2–5）</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>模型</translation>
    </message>
    <message>
        <source>Single beam (each on its own)</source>
        <translation>单波束（各波束独立）</translation>
    </message>
    <message>
        <source>Dual beam (eq. 3)</source>
        <translation>双波束（式 3）</translation>
    </message>
    <message>
        <source>Solve the range biases Δρ</source>
        <translation>解算距离偏差 Δρ</translation>
    </message>
    <message>
        <source>Rigid beams (relative rotation fixed)</source>
        <translation>刚性波束（固定相对旋转）</translation>
    </message>
    <message>
        <source>σ horizontal</source>
        <translation>σ 水平</translation>
    </message>
    <message>
        <source>σ vertical</source>
        <translation>σ 垂直</translation>
    </message>
    <message>
        <source>σ range</source>
        <translation>σ 测距</translation>
    </message>
    <message>
        <source>σ attitude</source>
        <translation>σ 姿态</translation>
    </message>
    <message>
        <source>σ orbit</source>
        <translation>σ 轨道</translation>
    </message>
    <message>
        <source>Waveform and feature match (eq. 1)</source>
        <translation>波形与地物匹配（式 1）</translation>
    </message>
    <message>
        <source>thred_h</source>
        <translation>thred_h</translation>
    </message>
    <message>
        <source>Incidence θ</source>
        <translation>入射角 θ</translation>
    </message>
    <message>
        <source>Peak-search smoothing</source>
        <translation>寻峰平滑</translation>
    </message>
    <message>
        <source>Min. separation</source>
        <translation>最小间隔</translation>
    </message>
    <message>
        <source>Sample interval</source>
        <translation>采样间隔</translation>
    </message>
</context>
<context>
    <name>lwb::ui::CalibWorkspace</name>
    <message>
        <source>Detector array, pointing and validation</source>
        <translation>探测器阵列、指向与验证</translation>
    </message>
    <message>
        <source>Waveform match</source>
        <translation>波形匹配</translation>
    </message>
    <message>
        <source>Demo</source>
        <translation>演示</translation>
    </message>
    <message>
        <source>Simulated inputs with known truth: detector array, calibration passes, check passes, waveform</source>
        <translation>真值已知的模拟输入：探测器阵列、定标过境、检查过境、波形</translation>
    </message>
    <message>
        <source>Detectors…</source>
        <translation>探测器…</translation>
    </message>
    <message>
        <source>Detector CSV: id, e, n (m) or lat, lon (deg), energy [, h, triggered, saturated]</source>
        <translation>探测器 CSV：id, e, n (m) 或 lat, lon (°), energy [, h, triggered, saturated]</translation>
    </message>
    <message>
        <source>Control points…</source>
        <translation>控制点…</translation>
    </message>
    <message>
        <source>Control-point CSV of calib pointing; beams.json beside it gives the beam designs</source>
        <translation>用于 calib pointing 的控制点 CSV；同目录下的 beams.json 提供波束设计值</translation>
    </message>
    <message>
        <source>Check points…</source>
        <translation>检查点…</translation>
    </message>
    <message>
        <source>Independent check points (control-point CSV): validation of the calibration</source>
        <translation>独立检查点（控制点 CSV 格式）：用于验证定标结果</translation>
    </message>
    <message>
        <source>Differences…</source>
        <translation>差值…</translation>
    </message>
    <message>
        <source>Elevation differences CSV: d (or diff, dh), or laser and control; optional group column</source>
        <translation>高程差 CSV：d 列（或 diff、dh），或 laser 与 control 两列；可选分组列 group</translation>
    </message>
    <message>
        <source>Waveform…</source>
        <translation>波形…</translation>
    </message>
    <message>
        <source>Waveform CSV: amplitude [, time_ns | sample]</source>
        <translation>波形 CSV：amplitude [, time_ns | sample]</translation>
    </message>
    <message>
        <source>Candidates…</source>
        <translation>候选地物…</translation>
    </message>
    <message>
        <source>Candidate features CSV: id, h [, e, n | lat, lon]</source>
        <translation>候选地物 CSV：id, h [, e, n | lat, lon]</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Cannot open %1</source>
        <translation>无法打开 %1</translation>
    </message>
    <message>
        <source>CSV (*.csv *.txt);;All files (*)</source>
        <translation>CSV 文件 (*.csv *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Detector array</source>
        <translation>探测器阵列</translation>
    </message>
    <message>
        <source>Control points</source>
        <translation>控制点</translation>
    </message>
    <message>
        <source>Beam designs (JSON) for %1</source>
        <translation>%1 的波束设计值（JSON）</translation>
    </message>
    <message>
        <source>JSON (*.json);;All files (*)</source>
        <translation>JSON 文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Check points</source>
        <translation>检查点</translation>
    </message>
    <message>
        <source>Elevation differences</source>
        <translation>高程差</translation>
    </message>
    <message>
        <source>Group column</source>
        <translation>分组列</translation>
    </message>
    <message>
        <source>Column that splits the differences (e.g. beam); empty for one group:</source>
        <translation>用于划分差值的列（如 beam）；留空则为一组：</translation>
    </message>
    <message>
        <source>Waveform</source>
        <translation>波形</translation>
    </message>
    <message>
        <source>Candidate features</source>
        <translation>候选地物</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Detector report (per detector)…</source>
        <translation>探测器报告（逐探测器）…</translation>
    </message>
    <message>
        <source>Export detector report</source>
        <translation>导出探测器报告</translation>
    </message>
    <message>
        <source>Footprint centre and surface…</source>
        <translation>足印中心与曲面…</translation>
    </message>
    <message>
        <source>Export footprint centre</source>
        <translation>导出足印中心</translation>
    </message>
    <message>
        <source>Calibrated parameters…</source>
        <translation>定标参数…</translation>
    </message>
    <message>
        <source>Export calibrated parameters</source>
        <translation>导出定标参数</translation>
    </message>
    <message>
        <source>Calibration iterations…</source>
        <translation>定标迭代过程…</translation>
    </message>
    <message>
        <source>Export iterations</source>
        <translation>导出迭代过程</translation>
    </message>
    <message>
        <source>Validation statistics…</source>
        <translation>验证统计…</translation>
    </message>
    <message>
        <source>Export statistics</source>
        <translation>导出统计</translation>
    </message>
    <message>
        <source>Candidate ranking…</source>
        <translation>候选排序…</translation>
    </message>
    <message>
        <source>Export candidate ranking</source>
        <translation>导出候选排序</translation>
    </message>
    <message>
        <source>Detector energies and the fitted footprint</source>
        <translation>探测器能量与拟合足印</translation>
    </message>
    <message>
        <source>East (m)</source>
        <translation>东向 (m)</translation>
    </message>
    <message>
        <source>North (m)</source>
        <translation>北向 (m)</translation>
    </message>
    <message>
        <source>Energy (file unit)</source>
        <translation>能量（文件单位）</translation>
    </message>
    <message>
        <source>energy</source>
        <translation>能量</translation>
    </message>
    <message>
        <source>Footprint centre: uncertainty</source>
        <translation>足印中心：不确定度</translation>
    </message>
    <message>
        <source>ΔEast from the fitted centre (cm)</source>
        <translation>相对拟合中心的 Δ东 (cm)</translation>
    </message>
    <message>
        <source>ΔNorth (cm)</source>
        <translation>Δ北 (cm)</translation>
    </message>
    <message>
        <source>Pointing &amp; range fit: convergence</source>
        <translation>指向与测距拟合：收敛</translation>
    </message>
    <message>
        <source>Iteration (0 = design)</source>
        <translation>迭代（0 = 设计值）</translation>
    </message>
    <message>
        <source>χ²</source>
        <translation>χ²</translation>
    </message>
    <message>
        <source>Pointing &amp; range calibration (eq. 2–5): χ² of the whitened residuals (left) and the RMS residuals in metres (right) per iteration; iteration 0 is the design values</source>
        <translation>指向与测距定标（式 2–5）：每次迭代的白化残差 χ²（左）与以米为单位的 RMS 残差（右）；第 0 次迭代为设计值</translation>
    </message>
    <message>
        <source>RMS (m)</source>
        <translation>RMS (m)</translation>
    </message>
    <message>
        <source>Detector fit: convergence</source>
        <translation>探测器拟合：收敛</translation>
    </message>
    <message>
        <source>Accepted LM step</source>
        <translation>接受的 LM 步</translation>
    </message>
    <message>
        <source>Detector surface fit (paper 002 §3.2.3): χ² of the weighted energies after each accepted Levenberg–Marquardt step</source>
        <translation>探测器曲面拟合（文献 002 §3.2.3）：每个被接受的 Levenberg–Marquardt（列文伯格–马夸尔特）迭代步之后加权能量的 χ²</translation>
    </message>
    <message>
        <source>Validation statistics</source>
        <translation>验证统计</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>Estimate</source>
        <translation>估计值</translation>
    </message>
    <message>
        <source>1σ</source>
        <translation>1σ</translation>
    </message>
    <message>
        <source>Simulated</source>
        <translation>模拟值</translation>
    </message>
    <message>
        <source>Error / σ</source>
        <translation>误差 / σ</translation>
    </message>
    <message>
        <source>Corrections Δα, Δβ, Δρ (eq. 2) and the calibrated three-axis pointing angles of the body frame (eq. 5)</source>
        <translation>改正量 Δα、Δβ、Δρ（式 2）以及本体坐标系定标后的三轴指向角（式 5）</translation>
    </message>
    <message>
        <source>(estimate − simulated) / 1σ: within ±3 in 99.7 % of honest fits</source>
        <translation>（估计值 − 模拟值）/ 1σ：正常拟合中 99.7 % 落在 ±3 以内</translation>
    </message>
    <message>
        <source>Calibrated parameters</source>
        <translation>定标参数</translation>
    </message>
    <message>
        <source>Convergence</source>
        <translation>收敛</translation>
    </message>
    <message>
        <source>Echo waveform: two Gaussian returns + baseline</source>
        <translation>回波波形：两个高斯回波 + 基线</translation>
    </message>
    <message>
        <source>Time (ns, two-way)</source>
        <translation>时间（ns，双程）</translation>
    </message>
    <message>
        <source>Amplitude (DN)</source>
        <translation>幅值 (DN)</translation>
    </message>
    <message>
        <source>Rank</source>
        <translation>排序</translation>
    </message>
    <message>
        <source>Candidate</source>
        <translation>候选</translation>
    </message>
    <message>
        <source>h (m)</source>
        <translation>h (m)</translation>
    </message>
    <message>
        <source>Δh (m)</source>
        <translation>Δh (m)</translation>
    </message>
    <message>
        <source>Δh ≤ thred_h</source>
        <translation>Δh ≤ thred_h</translation>
    </message>
    <message>
        <source>Footprint</source>
        <translation>足印</translation>
    </message>
    <message>
        <source>Surveyed height of the feature above the ground around it</source>
        <translation>地物相对其周边地面的实测高度</translation>
    </message>
    <message>
        <source>|h − h_waveform| (paper 002 eq. 1)</source>
        <translation>|h − h_waveform|（文献 002 式 1）</translation>
    </message>
    <message>
        <source>calibration parameters</source>
        <translation>定标参数</translation>
    </message>
    <message>
        <source>View</source>
        <translation>视图</translation>
    </message>
    <message>
        <source>Show the simulated truth (demo)</source>
        <translation>显示模拟真值（演示）</translation>
    </message>
    <message>
        <source>Energy colours</source>
        <translation>能量色表</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <source>Calibration demo: simulated detector array (energy noise 5 % + 2, set in the fit), 4 calibration passes and 22 check passes of both beams, a double-peak waveform</source>
        <translation>定标演示：模拟探测器阵列（能量噪声 5 % + 2，已在拟合中设定），两个波束的 4 次定标过境和 22 次检查过境，一条双峰波形</translation>
    </message>
    <message>
        <source>check points %1</source>
        <translation>检查点 %1</translation>
    </message>
    <message>
        <source>control-point residuals</source>
        <translation>控制点残差</translation>
    </message>
    <message>
        <source>&lt;b&gt;Detectors&lt;/b&gt; %1 · &lt;b&gt;control points&lt;/b&gt; %2 (beams %3) · &lt;b&gt;statistics&lt;/b&gt; %4 · &lt;b&gt;waveform&lt;/b&gt; %5 · &lt;b&gt;candidates&lt;/b&gt; %6</source>
        <translation>&lt;b&gt;探测器&lt;/b&gt; %1 · &lt;b&gt;控制点&lt;/b&gt; %2（波束 %3）· &lt;b&gt;统计&lt;/b&gt; %4 · &lt;b&gt;波形&lt;/b&gt; %5 · &lt;b&gt;候选&lt;/b&gt; %6</translation>
    </message>
    <message>
        <source>No detector array: open a detector CSV or the demo.</source>
        <translation>没有探测器阵列：请打开探测器 CSV 或演示数据。</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;Detector fit failed:&lt;/b&gt; %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;探测器拟合失败：&lt;/b&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>untriggered (no energy)</source>
        <translation>未触发（无能量）</translation>
    </message>
    <message>
        <source>set aside (outlier, or censoring off)</source>
        <translation>已剔除（粗差，或未启用删失处理）</translation>
    </message>
    <message>
        <source>in the fit as a bound (threshold / saturation)</source>
        <translation>作为界限参与拟合（阈值 / 饱和）</translation>
    </message>
    <message>
        <source>fitted footprint 1σ</source>
        <translation>拟合足印 1σ</translation>
    </message>
    <message>
        <source>1/e² (2σ)</source>
        <translation>1/e² (2σ)</translation>
    </message>
    <message>
        <source>fitted centre</source>
        <translation>拟合中心</translation>
    </message>
    <message>
        <source>simulated centre</source>
        <translation>模拟中心</translation>
    </message>
    <message>
        <source>1σ ellipse</source>
        <translation>1σ 误差椭圆</translation>
    </message>
    <message>
        <source>95 % ellipse (×%1)</source>
        <translation>95 % 误差椭圆（×%1）</translation>
    </message>
    <message>
        <source>χ² (best of 3 starts; 2 re-weightings)</source>
        <translation>χ²（3 个初值中最优；2 次重新加权）</translation>
    </message>
    <message>
        <source>dof = %1 (expected χ²)</source>
        <translation>自由度 = %1（χ² 期望值）</translation>
    </message>
    <message>
        <source>&lt;b&gt;Centre&lt;/b&gt; E %1 m, N %2 m · σ&lt;sub&gt;E&lt;/sub&gt; %3 m, σ&lt;sub&gt;N&lt;/sub&gt; %4 m · 1σ ellipse %5 × %6 m at %7°</source>
        <translation>&lt;b&gt;中心&lt;/b&gt; E %1 m，N %2 m · σ&lt;sub&gt;E&lt;/sub&gt; %3 m，σ&lt;sub&gt;N&lt;/sub&gt; %4 m · 1σ 误差椭圆 %5 × %6 m，方位 %7°</translation>
    </message>
    <message>
        <source>&lt;br&gt;lat %1°, lon %2°%3</source>
        <translation>&lt;br&gt;纬度 %1°，经度 %2°%3</translation>
    </message>
    <message>
        <source>, h %1 m</source>
        <translation>，h %1 m</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;span style=&apos;color:#2c8c2c&apos;&gt;Simulated centre E %1, N %2 m: fit − truth %3, %4 m = %5σ (Mahalanobis)&lt;/span&gt;</source>
        <translation>&lt;br&gt;&lt;span style=&apos;color:#2c8c2c&apos;&gt;模拟中心 E %1，N %2 m：拟合 − 真值 %3，%4 m = %5σ（马氏距离）&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Footprint&lt;/b&gt; σ %1 × %2 m at %3° · amplitude %4 ± %5 · background %6&lt;br&gt;&lt;b&gt;Fit&lt;/b&gt; %7 of %8 detectors · %9 dof · χ² %10 · RMS residual %11 · %12 steps</source>
        <translation>&lt;br&gt;&lt;b&gt;足印&lt;/b&gt; σ %1 × %2 m，方位 %3° · 幅值 %4 ± %5 · 背景 %6&lt;br&gt;&lt;b&gt;拟合&lt;/b&gt; %8 个探测器中用 %7 个 · 自由度 %9 · χ² %10 · RMS 残差 %11 · %12 步</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Noise&lt;/b&gt; %1</source>
        <translation>&lt;br&gt;&lt;b&gt;噪声&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>Doubtful: %1</source>
        <translation>存疑：%1</translation>
    </message>
    <message>
        <source>No control points: open a control-point CSV or the demo.</source>
        <translation>没有控制点：请打开控制点 CSV 或演示数据。</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;Calibration failed:&lt;/b&gt; %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;定标失败：&lt;/b&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>χ² (left)</source>
        <translation>χ²（左）</translation>
    </message>
    <message>
        <source>RMS plan (right)</source>
        <translation>平面 RMS（右）</translation>
    </message>
    <message>
        <source>RMS height (right)</source>
        <translation>高程 RMS（右）</translation>
    </message>
    <message>
        <source>beam %1 Δα (µrad)</source>
        <translation>波束 %1 Δα (µrad)</translation>
    </message>
    <message>
        <source>beam %1 Δβ (µrad)</source>
        <translation>波束 %1 Δβ (µrad)</translation>
    </message>
    <message>
        <source>beam %1 Δρ (m)</source>
        <translation>波束 %1 Δρ (m)</translation>
    </message>
    <message>
        <source>beam %1 Angle_X (°)</source>
        <translation>波束 %1 Angle_X (°)</translation>
    </message>
    <message>
        <source>beam %1 Angle_Y (°)</source>
        <translation>波束 %1 Angle_Y (°)</translation>
    </message>
    <message>
        <source>beam %1 Angle_Z (°)</source>
        <translation>波束 %1 Angle_Z (°)</translation>
    </message>
    <message>
        <source>relative rotation %1 (µrad)</source>
        <translation>相对旋转 %1 (µrad)</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1-beam model&lt;/b&gt;, %2 control points, %3 iterations%4 · RMS plan %5 → %6 m, height %7 → %8 m · χ² %9 for %10 dof</source>
        <translation>&lt;b&gt;%1波束模型&lt;/b&gt;，%2 个控制点，%3 次迭代%4 · 平面 RMS %5 → %6 m，高程 %7 → %8 m · χ² %9，自由度 %10</translation>
    </message>
    <message>
        <source>Dual</source>
        <translation>双</translation>
    </message>
    <message>
        <source>Single</source>
        <translation>单</translation>
    </message>
    <message>
        <source> (not converged)</source>
        <translation>（未收敛）</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;%1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>No elevation differences: open check points or a differences CSV.</source>
        <translation>没有高程差：请打开检查点或高程差 CSV。</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;small&gt;Paper 002&apos;s “RMSE” is the sample std for beam 1 but the RMS about zero for beam 2: read the labels.&lt;/small&gt;</source>
        <translation>&lt;br&gt;&lt;small&gt;文献 002 中的“RMSE”对波束 1 是样本标准差，对波束 2 却是相对零的 RMS：请注意区分各项标签。&lt;/small&gt;</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>mean (m)</source>
        <translation>均值 (m)</translation>
    </message>
    <message>
        <source>RMS about zero (m)</source>
        <translation>相对零的 RMS (m)</translation>
    </message>
    <message>
        <source>sample std, n−1 (m)</source>
        <translation>样本标准差，n−1 (m)</translation>
    </message>
    <message>
        <source>population std, n (m)</source>
        <translation>总体标准差，n (m)</translation>
    </message>
    <message>
        <source>min (m)</source>
        <translation>最小值 (m)</translation>
    </message>
    <message>
        <source>max (m)</source>
        <translation>最大值 (m)</translation>
    </message>
    <message>
        <source>median (m)</source>
        <translation>中位数 (m)</translation>
    </message>
    <message>
        <source>mean |d| (m)</source>
        <translation>|d| 均值 (m)</translation>
    </message>
    <message>
        <source>No waveform: open a waveform CSV or the demo.</source>
        <translation>没有波形：请打开波形 CSV 或演示数据。</translation>
    </message>
    <message>
        <source>samples</source>
        <translation>采样点</translation>
    </message>
    <message>
        <source>baseline</source>
        <translation>基线</translation>
    </message>
    <message>
        <source>top return (feature)</source>
        <translation>顶部回波（地物）</translation>
    </message>
    <message>
        <source>ground return</source>
        <translation>地面回波</translation>
    </message>
    <message>
        <source>fitted model</source>
        <translation>拟合模型</translation>
    </message>
    <message>
        <source>Δt = %1 ns → h = %2 m</source>
        <translation>Δt = %1 ns → h = %2 m</translation>
    </message>
    <message>
        <source>&lt;b&gt;Returns&lt;/b&gt; at %1 ± %2 and %3 ± %4 ns (σ %5 and %6 ns)&lt;br&gt;&lt;b&gt;Δt&lt;/b&gt; %7 ± %8 ns two-way · &lt;b&gt;h_waveform&lt;/b&gt; = Δt·c/2/cos θ = &lt;b&gt;%9 ± %10 m&lt;/b&gt; (θ = %11°)&lt;br&gt;RMS residual %12 · %13 iterations</source>
        <translation>&lt;b&gt;回波&lt;/b&gt;位于 %1 ± %2 与 %3 ± %4 ns（σ %5 与 %6 ns）&lt;br&gt;&lt;b&gt;Δt&lt;/b&gt; %7 ± %8 ns（双程）· &lt;b&gt;h_waveform&lt;/b&gt; = Δt·c/2/cos θ = &lt;b&gt;%9 ± %10 m&lt;/b&gt;（θ = %11°）&lt;br&gt;RMS 残差 %12 · %13 次迭代</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;span style=&apos;color:#2c8c2c&apos;&gt;Simulated feature height %1 m&lt;/span&gt;</source>
        <translation>&lt;br&gt;&lt;span style=&apos;color:#2c8c2c&apos;&gt;模拟地物高度 %1 m&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;Decomposition failed:&lt;/b&gt; %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;波形分解失败：&lt;/b&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>◀ here</source>
        <translation>◀ 此处</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Footprint on %1&lt;/b&gt; (Δh %2 m ≤ thred_h %3 m)</source>
        <translation>&lt;br&gt;&lt;b&gt;足印位于 %1&lt;/b&gt;（Δh %2 m ≤ thred_h %3 m）</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;No candidate within thred_h %1 m&lt;/b&gt; (closest %2, Δh %3 m)</source>
        <translation>&lt;br&gt;&lt;b&gt;没有候选地物在 thred_h %1 m 以内&lt;/b&gt;（最接近 %2，Δh %3 m）</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;span style=&apos;color:#c0392b&apos;&gt;%1&lt;/span&gt;</source>
        <translation>&lt;br&gt;&lt;span style=&apos;color:#c0392b&apos;&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;br&gt;No candidate features: open a candidates CSV to locate the footprint.</source>
        <translation>&lt;br&gt;没有候选地物：请打开候选地物 CSV 以确定足印位置。</translation>
    </message>
    <message>
        <source>calibration inputs: %1 must be a path, &quot;demo&quot; or empty</source>
        <translation>定标输入：%1 必须是路径、&quot;demo&quot; 或空</translation>
    </message>
    <message>
        <source>calibration view: colour map %1 out of range</source>
        <translation>定标视图：色表 %1 超出范围</translation>
    </message>
    <message>
        <source>calibration inputs: %1</source>
        <translation>定标输入：%1</translation>
    </message>
    <message>
        <source>Altimeter calibration</source>
        <translation>测高仪定标</translation>
    </message>
    <message>
        <source>a simulated calibration</source>
        <translation>一组模拟定标数据</translation>
    </message>
    <message>
        <source>beam %1</source>
        <translation>波束 %1</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ColorBar</name>
    <message>
        <source>Colour scale between the display limits (DN). Drag: bias (left/right) and contrast (up/down), as DS9; double-click: reset</source>
        <translation>显示范围之间的色标（DN）。拖动：左右调节偏置、上下调节对比度（同 DS9）；双击：重置</translation>
    </message>
    <message>
        <source>DN</source>
        <translation>DN</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ColorMaps</name>
    <message>
        <source>Gray</source>
        <translation>灰度</translation>
    </message>
    <message>
        <source>Min–max</source>
        <translation>最小–最大</translation>
    </message>
    <message>
        <source>Percentile 1–99.5</source>
        <translation>百分位 1–99.5</translation>
    </message>
    <message>
        <source>Square root</source>
        <translation>平方根</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ColumnPlot</name>
    <message>
        <source>Column along x (every numeric column of the shot list, and the time)</source>
        <translation>x 轴所用的列（影像列表中的所有数值列及时间）</translation>
    </message>
    <message>
        <source>Column along y</source>
        <translation>y 轴所用的列</translation>
    </message>
    <message>
        <source>&amp;X:</source>
        <translation>横轴(&amp;X)：</translation>
    </message>
    <message>
        <source>&amp;Y:</source>
        <translation>纵轴(&amp;Y)：</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>current shot</source>
        <translation>当前影像</translation>
    </message>
    <message>
        <source>%1 of the %2 shots in view have both %3 and %4%5. Click a point to open its shot.</source>
        <translation>视图中的 %2 幅影像里有 %1 幅同时具有 %3 和 %4%5。单击某点可打开对应影像。</translation>
    </message>
    <message>
        <source> (the table&apos;s filter applies; %1 shots in all)</source>
        <translation>（已应用表格筛选；共 %1 幅影像）</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ContactSheet</name>
    <message>
        <source>Arrow keys move; Enter or a click opens the shot in the review</source>
        <translation>方向键移动；按 Enter 或单击可在复核中打开该影像</translation>
    </message>
</context>
<context>
    <name>lwb::ui::DisplayControls</name>
    <message>
        <source>Min–max</source>
        <translation>最小–最大</translation>
    </message>
    <message>
        <source>ZScale</source>
        <translation>ZScale</translation>
    </message>
    <message>
        <source>99.5 %</source>
        <translation>99.5 %</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>手动</translation>
    </message>
    <message>
        <source>Display limits: the ROI&apos;s min and max, IRAF zscale (as DS9), the 0.5–99.5 percentiles, or the low and high values typed here</source>
        <translation>显示范围：ROI 的最小值和最大值、IRAF zscale（同 DS9）、0.5–99.5 百分位，或在此输入的下限和上限</translation>
    </message>
    <message>
        <source>Stretch between the limits: linear, sqrt, log (a = 1000) or asinh (as DS9)</source>
        <translation>上下限之间的拉伸方式：线性、平方根、对数（a = 1000）或反双曲正弦（同 DS9）</translation>
    </message>
    <message>
        <source> DN</source>
        <translation> DN</translation>
    </message>
    <message>
        <source>Low display limit (DN); editable in manual mode</source>
        <translation>显示下限（DN）；手动模式下可编辑</translation>
    </message>
    <message>
        <source>High display limit (DN); editable in manual mode</source>
        <translation>显示上限（DN）；手动模式下可编辑</translation>
    </message>
</context>
<context>
    <name>lwb::ui::FilterField</name>
    <message>
        <source>&lt;p style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;The filter shown is still the last valid one.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;当前显示的仍是上一个有效的筛选条件。&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>lwb::ui::FootprintController</name>
    <message numerus="yes">
        <source>Exported %n accepted shot(s) to %1</source>
        <translation>
            <numerusform>已将 %n 幅接受的影像导出到 %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n accepted shot(s) without a position (no fit) left out</source>
        <translation>
            <numerusform>；另有 %n 幅接受的影像没有位置（未拟合），未导出</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>lwb::ui::FootprintParamsPanel</name>
    <message>
        <source>Method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>Gray centroid (baseline)</source>
        <translation>灰度质心（基准方法）</translation>
    </message>
    <message>
        <source>TEFM (threshold + ellipse)</source>
        <translation>TEFM（阈值 + 椭圆）</translation>
    </message>
    <message>
        <source>Gaussian fit (Wu + Guo + LM)</source>
        <translation>高斯拟合（Wu + Guo + LM）</translation>
    </message>
    <message>
        <source>Verdict criteria of a paper (wu2021, yao2021), or a saved preset (every parameter)</source>
        <translation>论文中的判定准则（wu2021、yao2021），或已保存的预设（全部参数）</translation>
    </message>
    <message>
        <source>Save…</source>
        <translation>保存…</translation>
    </message>
    <message>
        <source>Save the current parameters as a preset (the CLI reads it with --config)</source>
        <translation>将当前参数保存为预设（命令行工具通过 --config 读取）</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>预设</translation>
    </message>
    <message>
        <source>Spot domain</source>
        <translation>光斑域</translation>
    </message>
    <message>
        <source>Threshold factor</source>
        <translation>阈值系数</translation>
    </message>
    <message>
        <source>Min. peak SNR</source>
        <translation>最小峰值 SNR</translation>
    </message>
    <message>
        <source>TEFM</source>
        <translation>TEFM</translation>
    </message>
    <message>
        <source>Background offset</source>
        <translation>背景偏移</translation>
    </message>
    <message>
        <source>Erosion size</source>
        <translation>腐蚀尺寸</translation>
    </message>
    <message>
        <source>Verdict criteria</source>
        <translation>判定准则</translation>
    </message>
    <message>
        <source>Axis ratio C = σx/σy</source>
        <translation>轴比 C = σx/σy</translation>
    </message>
    <message>
        <source>Major axis L_A</source>
        <translation>长轴 L_A</translation>
    </message>
    <message>
        <source>Tilt θ</source>
        <translation>倾角 θ</translation>
    </message>
    <message>
        <source>Eccentricity</source>
        <translation>偏心率</translation>
    </message>
    <message>
        <source>MSE below</source>
        <translation>MSE 低于</translation>
    </message>
    <message>
        <source>Uncertainty at most</source>
        <translation>不确定度不超过</translation>
    </message>
    <message>
        <source>Spot must not touch the ROI edge</source>
        <translation>光斑不得触及 ROI 边缘</translation>
    </message>
    <message>
        <source>No saturated pixels</source>
        <translation>无饱和像素</translation>
    </message>
    <message>
        <source>No second spot above</source>
        <translation>无次光斑高于</translation>
    </message>
    <message>
        <source>  of main peak</source>
        <translation>  （相对主峰）</translation>
    </message>
    <message>
        <source>Advanced (every other parameter)</source>
        <translation>高级（其余全部参数）</translation>
    </message>
    <message>
        <source>%1 (saved)</source>
        <translation>%1（已保存）</translation>
    </message>
    <message>
        <source>unknown preset &quot;%1&quot;</source>
        <translation>未知预设“%1”</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>保存预设</translation>
    </message>
    <message>
        <source>Preset name:</source>
        <translation>预设名称：</translation>
    </message>
</context>
<context>
    <name>lwb::ui::FootprintWorkspace</name>
    <message>
        <source>Move the cursor over the ROI for pixel values</source>
        <translation>将光标移到 ROI 上可查看像素值</translation>
    </message>
    <message>
        <source>Shots</source>
        <translation>影像</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>参数</translation>
    </message>
    <message>
        <source>All shots</source>
        <translation>全部影像</translation>
    </message>
    <message>
        <source>Good only</source>
        <translation>仅合格</translation>
    </message>
    <message>
        <source>Doubtful only</source>
        <translation>仅存疑</translation>
    </message>
    <message>
        <source>Rejected only</source>
        <translation>仅剔除</translation>
    </message>
    <message>
        <source>Unreadable only</source>
        <translation>仅无法读取</translation>
    </message>
    <message>
        <source>Manual verdicts</source>
        <translation>人工判定</translation>
    </message>
    <message>
        <source>Which shots the table and the contact sheet show (Alt+O)</source>
        <translation>表格和缩略图总览中显示哪些影像（Alt+O）</translation>
    </message>
    <message>
        <source>Sh&amp;ow:</source>
        <translation>显示(&amp;O)：</translation>
    </message>
    <message>
        <source>e.g. snr &lt; 10 and beam == 2</source>
        <translation>例如 snr &lt; 10 and beam == 2</translation>
    </message>
    <message>
        <source>F&amp;ilter:</source>
        <translation>筛选(&amp;I)：</translation>
    </message>
    <message>
        <source>Shots the pipeline judged doubtful that have a manual verdict. N goes to the next shot of the view without one</source>
        <translation>流程判定为存疑且已有人工判定的影像。按 N 转到视图中下一幅尚无人工判定的影像</translation>
    </message>
    <message>
        <source>unreadable (manual)</source>
        <translation>无法读取（人工）</translation>
    </message>
    <message>
        <source>Accept (A)</source>
        <translation>接受（A）</translation>
    </message>
    <message>
        <source>Reject (R)</source>
        <translation>剔除（R）</translation>
    </message>
    <message>
        <source>Next unreviewed (N)</source>
        <translation>下一幅未复核（N）</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Manual verdict good for this shot, then the next shot of the view (A)</source>
        <translation>将此影像人工判定为合格，然后转到视图中的下一幅影像（A）</translation>
    </message>
    <message>
        <source>Manual verdict rejected for this shot, then the next shot of the view (R)</source>
        <translation>将此影像人工判定为剔除，然后转到视图中的下一幅影像（R）</translation>
    </message>
    <message>
        <source>The next shot of the view that has no manual verdict yet (N)</source>
        <translation>视图中下一幅尚无人工判定的影像（N）</translation>
    </message>
    <message>
        <source>Drop the manual verdict and use the computed one</source>
        <translation>撤除人工判定，改用计算得到的判定</translation>
    </message>
    <message>
        <source>Blink / tile (B)</source>
        <translation>闪烁比对 / 平铺（B）</translation>
    </message>
    <message>
        <source>The selected shots (Ctrl+click, Shift+click) in a grid or blinking, zoom and display locked (B)</source>
        <translation>将选中的影像（Ctrl+单击、Shift+单击）以网格或闪烁方式显示，缩放和显示设置同步锁定（B）</translation>
    </message>
    <message>
        <source>Note on this shot (E; Enter keeps it and goes back to the list)</source>
        <translation>此影像的备注（E；按 Enter 保存并返回列表）</translation>
    </message>
    <message>
        <source>Kept in the session and the review table export</source>
        <translation>保存在会话和导出的复核表中</translation>
    </message>
    <message>
        <source>Colour map of the ROI, the frame and the contact sheet</source>
        <translation>ROI、帧和缩略图总览的色表</translation>
    </message>
    <message>
        <source>Gaussian 1/e²</source>
        <translation>高斯 1/e²</translation>
    </message>
    <message>
        <source>TEFM ellipse</source>
        <translation>TEFM 椭圆</translation>
    </message>
    <message>
        <source>Domain</source>
        <translation>光斑域</translation>
    </message>
    <message>
        <source>Centres</source>
        <translation>中心</translation>
    </message>
    <message>
        <source>Colours:</source>
        <translation>色表：</translation>
    </message>
    <message>
        <source>Draw:</source>
        <translation>绘制：</translation>
    </message>
    <message>
        <source>Regions: right-click a view ▸ Mouse: box / circle regions</source>
        <translation>区域：右键单击视图 ▸ 鼠标：矩形框 / 圆区域</translation>
    </message>
    <message>
        <source>Review</source>
        <translation>复核</translation>
    </message>
    <message>
        <source>Contact sheet</source>
        <translation>缩略图总览</translation>
    </message>
    <message>
        <source>Trend</source>
        <translation>趋势</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>绘图</translation>
    </message>
    <message>
        <source>ROI</source>
        <translation>ROI</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>帧</translation>
    </message>
    <message>
        <source>Pixel (%1, %2): %3 DN</source>
        <translation>像素 (%1, %2)：%3 DN</translation>
    </message>
    <message>
        <source>Frame pixel (%1, %2): %3 DN</source>
        <translation>帧像素 (%1, %2)：%3 DN</translation>
    </message>
    <message>
        <source>footprint parameters</source>
        <translation>足印参数</translation>
    </message>
    <message>
        <source>%v / %m shots</source>
        <translation>%v / %m 幅影像</translation>
    </message>
    <message>
        <source>Cannot open the footprint inputs</source>
        <translation>无法打开足印输入</translation>
    </message>
    <message>
        <source>Loaded %1 of %2 shots</source>
        <translation>已加载 %1 / %2 幅影像</translation>
    </message>
    <message>
        <source>Loading cancelled after %1 shots</source>
        <translation>加载 %1 幅影像后已取消</translation>
    </message>
    <message>
        <source>Loaded %1 shots (%2 unreadable)</source>
        <translation>已加载 %1 幅影像（%2 幅无法读取）</translation>
    </message>
    <message>
        <source>; skipped %1 %2 that %3 not an image (%4%5)</source>
        <translation>；跳过了 %1 个%3图像的%2（%4%5）</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>files</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>is</source>
        <translation>不是</translation>
    </message>
    <message>
        <source>are</source>
        <translation>不是</translation>
    </message>
    <message>
        <source>note and verdict on %1</source>
        <translation>%1 的备注和判定</translation>
    </message>
    <message>
        <source>Last shot of the view</source>
        <translation>已是视图中的最后一幅影像</translation>
    </message>
    <message>
        <source>Every shot of this view has a manual verdict</source>
        <translation>此视图中的每幅影像都已有人工判定</translation>
    </message>
    <message>
        <source>Export accepted shots</source>
        <translation>导出接受的影像</translation>
    </message>
    <message>
        <source>Export the review table</source>
        <translation>导出复核表</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Cannot export: %1</source>
        <translation>无法导出：%1</translation>
    </message>
    <message>
        <source>Exported the review table (%1 shots) to %2</source>
        <translation>已将复核表（%1 幅影像）导出到 %2</translation>
    </message>
    <message>
        <source>Blink / tile needs two shots with an image: select them in the table (Ctrl+click, Shift+click)</source>
        <translation>闪烁比对 / 平铺需要至少两幅含图像的影像：请在表格中选择（Ctrl+单击、Shift+单击）</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#2e8b57&apos;&gt;%1 good&lt;/span&gt; · &lt;span style=&apos;color:#d68910&apos;&gt;%2 doubtful&lt;/span&gt; · &lt;span style=&apos;color:#c0392b&apos;&gt;%3 rejected&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#2e8b57&apos;&gt;合格 %1&lt;/span&gt; · &lt;span style=&apos;color:#d68910&apos;&gt;存疑 %2&lt;/span&gt; · &lt;span style=&apos;color:#c0392b&apos;&gt;剔除 %3&lt;/span&gt;</translation>
    </message>
    <message>
        <source> · &lt;span style=&apos;color:#6e6e78&apos;&gt;%1 unreadable&lt;/span&gt;</source>
        <translation> · &lt;span style=&apos;color:#6e6e78&apos;&gt;无法读取 %1&lt;/span&gt;</translation>
    </message>
    <message>
        <source> · %1 pending</source>
        <translation> · 待定 %1</translation>
    </message>
    <message>
        <source> · %1 manual</source>
        <translation> · 人工 %1</translation>
    </message>
    <message>
        <source> · &lt;b&gt;%1 of %2 shown&lt;/b&gt;</source>
        <translation> · &lt;b&gt;显示 %1 / %2&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Reviewed %1 of %2 doubtful</source>
        <translation>已复核 %1 / %2 幅存疑影像</translation>
    </message>
    <message>
        <source>Unreadable: %1</source>
        <translation>无法读取：%1</translation>
    </message>
    <message>
        <source>Not loaded yet</source>
        <translation>尚未加载</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2</translation>
    </message>
    <message>
        <source> (manual; computed: %1)</source>
        <translation>（人工；计算结果：%1）</translation>
    </message>
    <message>
        <source>Frame around the ROI</source>
        <translation>ROI 周围的帧</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; — %2</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; — %2</translation>
    </message>
    <message>
        <source> (stage %1)</source>
        <translation>（第 %1 阶段）</translation>
    </message>
    <message>
        <source> · noise class &lt;b&gt;%1&lt;/b&gt;, background %2 DN ± %3</source>
        <translation> · 噪声类别 &lt;b&gt;%1&lt;/b&gt;，背景 %2 DN ± %3</translation>
    </message>
    <message>
        <source>&lt;br&gt;centre (%1, %2) px ± %3 · CRLB %4 px · σx %5 σy %6 px · C %7 · θ %8° · L_A %9 px</source>
        <translation>&lt;br&gt;中心 (%1, %2) px ± %3 · CRLB %4 px · σx %5 σy %6 px · C %7 · θ %8° · L_A %9 px</translation>
    </message>
    <message>
        <source>&lt;br&gt;e %1 · area %2 px · MSE %3 · SNR %4 · amplitude %5 DN</source>
        <translation>&lt;br&gt;e %1 · 面积 %2 px · MSE %3 · SNR %4 · 振幅 %5 DN</translation>
    </message>
    <message>
        <source>ΔX (px)</source>
        <translation>ΔX (px)</translation>
    </message>
    <message>
        <source>Change of the spot centre&apos;s x from the first month&apos;s mean (px): each shot (dots) and the monthly mean (line)</source>
        <translation>光斑中心 x 相对首月均值的变化（px）：各影像（点）与月均值（线）</translation>
    </message>
    <message>
        <source>ΔY (px)</source>
        <translation>ΔY (px)</translation>
    </message>
    <message>
        <source>Change of the spot centre&apos;s y from the first month&apos;s mean (px): each shot (dots) and the monthly mean (line)</source>
        <translation>光斑中心 y 相对首月均值的变化（px）：各影像（点）与月均值（线）</translation>
    </message>
    <message>
        <source>Pointing (″)</source>
        <translation>指向（″）</translation>
    </message>
    <message>
        <source>Planar pointing change from the first month (arcsec)</source>
        <translation>相对首月的平面指向变化（角秒）</translation>
    </message>
    <message>
        <source>Filter: %1 (the previous filter stays)</source>
        <translation>筛选：%1（保留上一个筛选条件）</translation>
    </message>
    <message>
        <source>Filter cleared</source>
        <translation>已清除筛选</translation>
    </message>
    <message>
        <source>Filter: %1 of %2 shots</source>
        <translation>筛选：%1 / %2 幅影像</translation>
    </message>
    <message>
        <source>Trend: %1. A shot list CSV with time and beam columns (or the demo) gives the monthly centroid trend.</source>
        <translation>趋势：%1。含时间列和波束列的影像列表 CSV（或演示数据）可给出逐月质心趋势。</translation>
    </message>
    <message>
        <source>beam </source>
        <translation>波束 </translation>
    </message>
    <message>
        <source> shots</source>
        <translation> 幅影像</translation>
    </message>
    <message>
        <source>%1: %2″ planar pointing change by the last month. </source>
        <translation>%1：截至最后一个月，平面指向变化 %2″。</translation>
    </message>
    <message>
        <source>Filter applied: the trend of the %1 of %2 shots in view (%3). </source>
        <translation>已应用筛选：视图中 %2 幅影像里 %1 幅的趋势（%3）。</translation>
    </message>
    <message>
        <source>Change from the first month: shots (dots) and monthly means (lines) of the accepted shots; 3σ rejection within each month; 0.31″ per px. </source>
        <translation>相对首月的变化：接受影像的逐幅值（点）和月均值（线）；每月内按 3σ 剔除；每像素 0.31″。</translation>
    </message>
    <message>
        <source>override of %1: unknown verdict &quot;%2&quot;</source>
        <translation>%1 的人工判定：未知判定“%2”</translation>
    </message>
    <message>
        <source>unknown filter &quot;%1&quot; (one of %2)</source>
        <translation>未知筛选“%1”（应为 %2 之一）</translation>
    </message>
    <message>
        <source>%1 simulated footprint shots</source>
        <translation>%1 幅模拟足印影像</translation>
    </message>
    <message>
        <source>Open footprint frames, a folder, or a shot list (CSV)</source>
        <translation>打开足印帧、文件夹或影像列表（CSV）</translation>
    </message>
    <message>
        <source>Frames and shot lists (*.png *.tif *.tiff *.pgm *.raw *.bin *.csv)</source>
        <translation>帧和影像列表 (*.png *.tif *.tiff *.pgm *.raw *.bin *.csv)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>所有文件 (*)</translation>
    </message>
    <message>
        <source>Open a folder of footprint frames</source>
        <translation>打开足印帧文件夹</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>无法导出</translation>
    </message>
    <message>
        <source>Frames, folder or shot list…</source>
        <translation>帧、文件夹或影像列表…</translation>
    </message>
    <message>
        <source>Accepted shots (CSV)…</source>
        <translation>接受的影像（CSV）…</translation>
    </message>
    <message>
        <source>Open footprint &amp;frames or shot list…</source>
        <translation>打开足印帧或影像列表(&amp;F)…</translation>
    </message>
    <message>
        <source>Open &amp;folder of footprint frames…</source>
        <translation>打开足印帧文件夹(&amp;F)…</translation>
    </message>
    <message>
        <source>Export accepted footprint shots…</source>
        <translation>导出接受的足印影像…</translation>
    </message>
    <message>
        <source>Export footprint review &amp;table…</source>
        <translation>导出足印复核表(&amp;T)…</translation>
    </message>
    <message>
        <source>↑ / ↓	Footprint ▸ previous / next shot</source>
        <translation>↑ / ↓	足印 ▸ 上一幅 / 下一幅影像</translation>
    </message>
    <message>
        <source>A	Footprint ▸ accept the shot and move on</source>
        <translation>A	足印 ▸ 接受该影像并转到下一幅</translation>
    </message>
    <message>
        <source>R	Footprint ▸ reject the shot and move on</source>
        <translation>R	足印 ▸ 剔除该影像并转到下一幅</translation>
    </message>
    <message>
        <source>N	Footprint ▸ next shot of the view without a manual verdict</source>
        <translation>N	足印 ▸ 视图中下一幅尚无人工判定的影像</translation>
    </message>
    <message>
        <source>E	Footprint ▸ note on the shot (Enter keeps it and returns to the table)</source>
        <translation>E	足印 ▸ 影像备注（按 Enter 保存并返回表格）</translation>
    </message>
    <message>
        <source>Tab, Shift+Tab	Footprint ▸ leave the shot table (the shot stays)</source>
        <translation>Tab, Shift+Tab	足印 ▸ 离开影像表格（当前影像不变）</translation>
    </message>
    <message>
        <source>2 / 4 / 8	Footprint ▸ zoom the ROI and frame views 2×, 4×, 8× the fit</source>
        <translation>2 / 4 / 8	足印 ▸ 将 ROI 和帧视图缩放为适合窗口大小的 2×、4×、8×</translation>
    </message>
    <message>
        <source>1	Footprint ▸ fit the ROI and frame views again</source>
        <translation>1	足印 ▸ 使 ROI 和帧视图重新适合窗口</translation>
    </message>
    <message>
        <source>B	Footprint ▸ blink / tile the selected shots (Ctrl+click, Shift+click select several)</source>
        <translation>B	足印 ▸ 闪烁比对 / 平铺选中的影像（Ctrl+单击、Shift+单击可多选）</translation>
    </message>
    <message>
        <source>Space, ← / →, T / B	Blink / tile ▸ play or pause, step, tile or blink</source>
        <translation>Space, ← / →, T / B	闪烁比对 / 平铺 ▸ 播放或暂停、逐幅切换、平铺或闪烁比对</translation>
    </message>
    <message>
        <source>Footprint review</source>
        <translation>足印复核</translation>
    </message>
    <message>
        <source>Suggesting thresholds %p%</source>
        <translation>正在建议阈值 %p%</translation>
    </message>
    <message>
        <source>Suggest thresholds…</source>
        <translation>建议阈值…</translation>
    </message>
    <message>
        <source>The verdict criteria tuned on the shots you gave a manual verdict (Accept / Reject): what would change, before and after, cross-validated; applied only if you accept</source>
        <translation>按您给出人工判定（接受 / 拒绝）的光斑调整判定准则：显示会改变什么、调整前后对比及交叉验证结果；仅在您接受后应用</translation>
    </message>
    <message>
        <source>No threshold suggestion yet</source>
        <translation>暂时无法建议阈值</translation>
    </message>
    <message>
        <source>The shots are still being processed: suggest again when they are done.</source>
        <translation>光斑仍在处理中：处理完成后再建议。</translation>
    </message>
    <message>
        <source>No threshold suggestion</source>
        <translation>无阈值建议</translation>
    </message>
    <message>
        <source>%1.
The criteria are tuned on the shots you gave a manual verdict (Accept A, Reject R): at least 10, some good and some not.</source>
        <translation>%1。
判定准则按您给出人工判定的光斑调整（接受 A、拒绝 R）：至少 10 个，且好与不好的都要有。</translation>
    </message>
    <message>
        <source>Thresholds suggested from your verdicts</source>
        <translation>根据您的判定建议的阈值</translation>
    </message>
    <message>
        <source>&lt;p&gt;Tuned on the &lt;b&gt;%1&lt;/b&gt; shots you gave a manual verdict.&lt;/p&gt;</source>
        <translation>&lt;p&gt;按您给出人工判定的 &lt;b&gt;%1&lt;/b&gt; 个光斑调整。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;No threshold moved: the current criteria are already the best found.&lt;/p&gt;</source>
        <translation>&lt;p&gt;没有阈值改变：当前准则已是找到的最优。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Criterion</source>
        <translation>准则</translation>
    </message>
    <message>
        <source>Now</source>
        <translation>当前</translation>
    </message>
    <message>
        <source>Suggested</source>
        <translation>建议</translation>
    </message>
    <message>
        <source>Held out</source>
        <translation>留出验证</translation>
    </message>
    <message>
        <source>Your good shots judged not good</source>
        <translation>您判为好的光斑被判为不好</translation>
    </message>
    <message>
        <source>Your other shots judged good</source>
        <translation>您未判为好的光斑被判为好</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;i&gt;Held out: each shot judged by criteria tuned without it (%1-fold cross-validation), what to expect on shots not yet reviewed.&lt;/i&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;i&gt;留出验证：每个光斑由不含它调整出的准则判定（%1 折交叉验证），即对尚未审阅的光斑的预期。&lt;/i&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>应用</translation>
    </message>
    <message>
        <source>Sets the suggested criteria in the parameters (one step: Edit &gt; Undo takes it back)</source>
        <translation>把建议的准则设为参数（一步操作：编辑 &gt; 撤销可还原）</translation>
    </message>
    <message>
        <source>min</source>
        <translation>最小</translation>
    </message>
    <message>
        <source>max</source>
        <translation>最大</translation>
    </message>
    <message>
        <source>verdict thresholds to the suggested ones</source>
        <translation>判定阈值为建议值</translation>
    </message>
    <message>
        <source>Strip: shots whose verdict would change along the slider (up to %1)</source>
        <translation>条带：沿滑块各值判定会改变的光斑数（最多 %1）</translation>
    </message>
    <message>
        <source>; orange: disagreements with your %1 manual verdicts (%2 to %3, fewest at %4)</source>
        <translation>；橙线：与您的 %1 个人工判定不一致的数目（%2 至 %3，在 %4 处最少）</translation>
    </message>
    <message>
        <source>The fit&apos;s parameters changed while the suggestion was made: suggest again.</source>
        <translation>计算建议期间拟合参数已改变：请重新建议。</translation>
    </message>
</context>
<context>
    <name>lwb::ui::HistogramView</name>
    <message>
        <source>Histogram of the ROI (log counts) with the display limits</source>
        <translation>ROI 直方图（计数取对数）及显示范围</translation>
    </message>
    <message>
        <source>%1 DN</source>
        <translation>%1 DN</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ImageRegions</name>
    <message>
        <source>Circle %1 (r %2 px at %3, %4)</source>
        <translation>圆 %1（r %2 px，位于 %3, %4）</translation>
    </message>
    <message>
        <source>Box %1 (%2 × %3 px at %4, %5)</source>
        <translation>矩形框 %1（%2 × %3 px，位于 %4, %5）</translation>
    </message>
    <message>
        <source>: n %1 · sum %2 · mean %3 · median %4 · σ %5 · min %6 · max %7</source>
        <translation>：n %1 · 总和 %2 · 均值 %3 · 中位数 %4 · σ %5 · 最小 %6 · 最大 %7</translation>
    </message>
    <message>
        <source> · centroid (%1, %2)</source>
        <translation> · 质心 (%1, %2)</translation>
    </message>
    <message>
        <source> · no centroid (sum ≤ 0)</source>
        <translation> · 无质心（总和 ≤ 0）</translation>
    </message>
    <message>
        <source> · %1 NaN left out</source>
        <translation> · 略去 %1 个 NaN</translation>
    </message>
    <message>
        <source> · %1 px outside the image</source>
        <translation> · %1 px 位于图像外</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ImageView</name>
    <message>
        <source>Wheel: zoom · drag: pan · right-drag or Shift+drag: zoom to the box · middle-drag or Ctrl+drag: contrast (up/down) and bias (left/right) · 2, 4, 8: zoom steps · 1, Home or double-click: fit · right-click: menu (regions, export)</source>
        <translation>滚轮：缩放 · 拖动：平移 · 右键拖动或 Shift+拖动：框选缩放 · 中键拖动或 Ctrl+拖动：对比度（上下）和偏置（左右）· 2、4、8：缩放档位 · 1、Home 或双击：适合窗口 · 右键单击：菜单（区域、导出）</translation>
    </message>
    <message>
        <source>1× (fit)	1, Home, double-click</source>
        <translation>1×（适合窗口）	1, Home, double-click</translation>
    </message>
    <message>
        <source>%1×	%1</source>
        <translation>%1×	%1</translation>
    </message>
    <message>
        <source>Box zoom: right-drag or Shift+drag</source>
        <translation>框选缩放：右键拖动或 Shift+拖动</translation>
    </message>
    <message>
        <source>Mouse: pan</source>
        <translation>鼠标：平移</translation>
    </message>
    <message>
        <source>Mouse: box regions</source>
        <translation>鼠标：矩形框区域</translation>
    </message>
    <message>
        <source>Mouse: circle regions</source>
        <translation>鼠标：圆区域</translation>
    </message>
    <message>
        <source>Delete region	Delete</source>
        <translation>删除区域	Delete</translation>
    </message>
    <message>
        <source>Delete all regions</source>
        <translation>删除所有区域</translation>
    </message>
    <message>
        <source>Reset contrast and bias</source>
        <translation>重置对比度和偏置</translation>
    </message>
    <message>
        <source>Contrast / bias: middle-drag or Ctrl+drag</source>
        <translation>对比度 / 偏置：中键拖动或 Ctrl+拖动</translation>
    </message>
    <message>
        <source>Export view (PNG, SVG, PDF)…</source>
        <translation>导出视图（PNG、SVG、PDF）…</translation>
    </message>
    <message>
        <source>no image to export</source>
        <translation>没有可导出的图像</translation>
    </message>
    <message>
        <source>cannot draw the view into %1</source>
        <translation>无法将视图绘制到 %1</translation>
    </message>
    <message>
        <source>Export view</source>
        <translation>导出视图</translation>
    </message>
    <message>
        <source>Width in pixels (the height follows the view):</source>
        <translation>宽度（像素；高度随视图比例）：</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF (*.pdf)</source>
        <translation>PNG 图像 (*.png);;SVG 图形 (*.svg);;PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Cannot export the view: %1</source>
        <translation>无法导出视图：%1</translation>
    </message>
    <message>
        <source>Exported the view (%1 × %2 px) to %3</source>
        <translation>已将视图（%1 × %2 px）导出到 %3</translation>
    </message>
    <message>
        <source>No image</source>
        <translation>无图像</translation>
    </message>
</context>
<context>
    <name>lwb::ui::MainWindow</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>就绪</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open… (current workspace)</source>
        <translation>打开(&amp;O)…（当前工作区）</translation>
    </message>
    <message>
        <source>Opens the inputs of the workspace in front</source>
        <translation>打开当前前台工作区的输入</translation>
    </message>
    <message>
        <source>Open &amp;demo</source>
        <translation>打开演示(&amp;D)</translation>
    </message>
    <message>
        <source>Recent &amp;inputs</source>
        <translation>最近的输入(&amp;I)</translation>
    </message>
    <message>
        <source>Open &amp;session…</source>
        <translation>打开会话(&amp;S)…</translation>
    </message>
    <message>
        <source>Ctrl+Shift+O</source>
        <translation>Ctrl+Shift+O</translation>
    </message>
    <message>
        <source>&amp;Recent sessions</source>
        <translation>最近的会话(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Save session</source>
        <translation>保存会话(&amp;S)</translation>
    </message>
    <message>
        <source>Save session &amp;as…</source>
        <translation>会话另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>&amp;Export… (current workspace)</source>
        <translation>导出(&amp;E)…（当前工作区）</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>&amp;Report… (PDF)</source>
        <translation>报告(&amp;R)…（PDF）</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <source>Ctrl+Y</source>
        <translation>Ctrl+Y</translation>
    </message>
    <message>
        <source>Copy as &amp;command line</source>
        <translation>复制为命令行(&amp;C)</translation>
    </message>
    <message>
        <source>No result here that a command reproduces</source>
        <translation>此处没有可由命令复现的结果</translation>
    </message>
    <message>
        <source>Copied: %1</source>
        <translation>已复制：%1</translation>
    </message>
    <message>
        <source>Copied (%1): %2</source>
        <translation>已复制（%1）：%2</translation>
    </message>
    <message>
        <source>Copy as &amp;Python</source>
        <translation>复制为 Python(&amp;P)</translation>
    </message>
    <message>
        <source>No result here that a script reproduces</source>
        <translation>此处没有可由脚本复现的结果</translation>
    </message>
    <message numerus="yes">
        <source>Copied the Python script (%n line(s))</source>
        <translation>
            <numerusform>已复制 Python 脚本（%n 行）</numerusform>
        </translation>
    </message>
    <message>
        <source>Copied the Python script (%1)</source>
        <translation>已复制 Python 脚本（%1）</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>Ctrl+%1</source>
        <translation>Ctrl+%1</translation>
    </message>
    <message>
        <source>&amp;Parameter panels</source>
        <translation>参数面板(&amp;P)</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <source>P&amp;anels</source>
        <translation>面板(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Reset panel layout</source>
        <translation>重置面板布局(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Status bar</source>
        <translation>状态栏(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;Full screen</source>
        <translation>全屏(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Light theme</source>
        <translation>浅色主题(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Dark theme</source>
        <translation>深色主题(&amp;D)</translation>
    </message>
    <message>
        <source>Lan&amp;guage</source>
        <translation>语言(&amp;G)</translation>
    </message>
    <message>
        <source>As the system (%1)</source>
        <translation>跟随系统（%1）</translation>
    </message>
    <message>
        <source>The interface will be in %1 from the next start of the workbench.</source>
        <translation>下次启动工作台时，界面将切换为%1。</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;User guide</source>
        <translation>用户指南(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>键盘快捷键(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>关于(&amp;A)</translation>
    </message>
    <message>
        <source>About Laser Workbench</source>
        <translation>关于激光工作台</translation>
    </message>
    <message>
        <source>&lt;b&gt;Laser Workbench&lt;/b&gt; %1&lt;br&gt;Footprint spot centres, SLR signal extraction, altimeter and radiometric calibration.&lt;br&gt;Every GUI action has a batch equivalent in &lt;tt&gt;laserwb-cli&lt;/tt&gt;.&lt;br&gt;&lt;br&gt;Free software under the GNU General Public License, version 3 or later. The methods and their papers: docs/algorithms.md and docs/references.md.</source>
        <translation>&lt;b&gt;激光工作台&lt;/b&gt; %1&lt;br&gt;足印光斑中心提取、卫星激光测距（SLR）信号提取、激光测高仪定标与辐射定标。&lt;br&gt;图形界面中的每项操作在 &lt;tt&gt;laserwb-cli&lt;/tt&gt; 中都有对应的批处理命令。&lt;br&gt;&lt;br&gt;本软件为自由软件，依据 GNU 通用公共许可证第 3 版或更高版本发布。所用方法及其文献见 docs/algorithms.md 和 docs/references.md。</translation>
    </message>
    <message>
        <source>Right-drag, Shift+drag	Image view ▸ box zoom</source>
        <translation>Right-drag, Shift+drag	图像视图 ▸ 框选缩放</translation>
    </message>
    <message>
        <source>Home, double-click	Image view ▸ fit</source>
        <translation>Home, double-click	图像视图 ▸ 适合窗口</translation>
    </message>
    <message>
        <source>Right-click	Image view ▸ menu: zoom steps, mouse mode (pan, box or circle regions), reset contrast and bias, export the view</source>
        <translation>Right-click	图像视图 ▸ 菜单：缩放档位、鼠标模式（平移、矩形框或圆区域）、重置对比度和偏置、导出视图</translation>
    </message>
    <message>
        <source>Middle-drag, Ctrl+drag	Image view ▸ contrast (up / down) and bias (left / right), as DS9&apos;s right-drag</source>
        <translation>Middle-drag, Ctrl+drag	图像视图 ▸ 对比度（上 / 下）和偏置（左 / 右），相当于 DS9 的右键拖动</translation>
    </message>
    <message>
        <source>Drag on the colour bar	Image view ▸ contrast and bias; a double-click on the bar resets them</source>
        <translation>Drag on the colour bar	图像视图 ▸ 对比度和偏置；双击色标条可将其重置</translation>
    </message>
    <message>
        <source>Drag (region mode)	Image view ▸ draw a box or circle region; drag a region to move it</source>
        <translation>Drag (region mode)	图像视图 ▸ 绘制矩形框或圆区域；拖动区域可移动它</translation>
    </message>
    <message>
        <source>Delete	Image view ▸ delete the selected region (the view reached by Tab)</source>
        <translation>Delete	图像视图 ▸ 删除选中的区域（在按 Tab 切换到的视图中）</translation>
    </message>
    <message>
        <source>Shift+drag	Parameter slider ▸ ten times finer than the mouse</source>
        <translation>Shift+drag	参数滑块 ▸ 比鼠标拖动精细十倍</translation>
    </message>
    <message>
        <source>Wheel	Plot ▸ zoom both axes about the cursor</source>
        <translation>Wheel	绘图 ▸ 以光标为中心缩放两个坐标轴</translation>
    </message>
    <message>
        <source>Shift+Wheel	Plot ▸ zoom x only</source>
        <translation>Shift+Wheel	绘图 ▸ 仅缩放 x 轴</translation>
    </message>
    <message>
        <source>Ctrl+Wheel	Plot ▸ zoom y only</source>
        <translation>Ctrl+Wheel	绘图 ▸ 仅缩放 y 轴</translation>
    </message>
    <message>
        <source>Wheel / drag over an axis	Plot ▸ zoom / pan that axis only</source>
        <translation>Wheel / drag over an axis	绘图 ▸ 仅缩放 / 平移该坐标轴</translation>
    </message>
    <message>
        <source>Drag	Plot ▸ pan</source>
        <translation>Drag	绘图 ▸ 平移</translation>
    </message>
    <message>
        <source>Right-drag, Shift+drag	Plot ▸ box zoom</source>
        <translation>Right-drag, Shift+drag	绘图 ▸ 框选缩放</translation>
    </message>
    <message>
        <source>Double-click, Home	Plot ▸ reset to the home view</source>
        <translation>Double-click, Home	绘图 ▸ 恢复初始视图</translation>
    </message>
    <message>
        <source>Backspace	Plot ▸ back in the zoom history</source>
        <translation>Backspace	绘图 ▸ 返回上一步缩放</translation>
    </message>
    <message>
        <source>Right-click	Plot ▸ export PNG / SVG / PDF, copy to the clipboard</source>
        <translation>Right-click	绘图 ▸ 导出 PNG / SVG / PDF，复制到剪贴板</translation>
    </message>
    <message>
        <source>Click a legend entry	Plot ▸ hide / show its series</source>
        <translation>Click a legend entry	绘图 ▸ 隐藏 / 显示对应的数据系列</translation>
    </message>
    <message>
        <source>Hover	Plot ▸ crosshair with the coordinates (a colour map&apos;s value too)</source>
        <translation>Hover	绘图 ▸ 显示带坐标的十字准线（色表图还显示数值）</translation>
    </message>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>键盘快捷键</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按键</translation>
    </message>
    <message>
        <source>What</source>
        <translation>功能</translation>
    </message>
    <message>
        <source>No report</source>
        <translation>无报告</translation>
    </message>
    <message>
        <source>%1 has no result to report yet.</source>
        <translation>%1 还没有可报告的结果。</translation>
    </message>
    <message>
        <source>This workspace</source>
        <translation>此工作区</translation>
    </message>
    <message>
        <source>Write report</source>
        <translation>生成报告</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF 文件 (*.pdf)</translation>
    </message>
    <message>
        <source>Report not written</source>
        <translation>未生成报告</translation>
    </message>
    <message>
        <source>nothing to report</source>
        <translation>没有可报告的内容</translation>
    </message>
    <message>
        <source>Report written: %1</source>
        <translation>已生成报告：%1</translation>
    </message>
    <message>
        <source>Laser Workbench — user guide</source>
        <translation>激光工作台 — 用户指南</translation>
    </message>
    <message>
        <source>The user guide is missing.</source>
        <translation>缺少用户指南。</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>%1%2 — Laser Workbench</source>
        <translation>%1%2 — 激光工作台</translation>
    </message>
    <message>
        <source>Built-in demo: %1</source>
        <translation>内置演示：%1</translation>
    </message>
    <message>
        <source>%1 and %2</source>
        <translation>%1和%2</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>%1: no such file or folder</source>
        <translation>%1：没有此文件或文件夹</translation>
    </message>
    <message>
        <source>%1: not a file the workbench opens (CRD, CPF, SINEX, O-C or shot-list CSV, images, a folder of frames, a session)</source>
        <translation>%1：不是工作台可打开的文件（CRD、CPF、SINEX、O-C 或影像列表 CSV、图像、帧文件夹、会话）</translation>
    </message>
    <message>
        <source>Cannot open everything given</source>
        <translation>无法打开全部给定的输入</translation>
    </message>
    <message>
        <source>%1: not an input of the %2 workspace</source>
        <translation>%1：不是 %2 工作区的输入</translation>
    </message>
    <message>
        <source>Nothing to open here</source>
        <translation>此处没有可打开的内容</translation>
    </message>
    <message>
        <source>Nothing to export here</source>
        <translation>此处没有可导出的内容</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>, pass %1</source>
        <translation>，过境 %1</translation>
    </message>
    <message>
        <source>Cannot open the recent input</source>
        <translation>无法打开最近的输入</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Cannot open the session</source>
        <translation>无法打开会话</translation>
    </message>
    <message>
        <source>%1: not opened (cancelled; the current changes are kept)</source>
        <translation>%1：未打开（已取消；当前更改保持不变）</translation>
    </message>
    <message>
        <source>%1: a session is a JSON object</source>
        <translation>%1：会话必须是一个 JSON 对象</translation>
    </message>
    <message>
        <source>%1: not a Laser Workbench session (no &quot;format&quot;: &quot;laserwb-session&quot;)</source>
        <translation>%1：不是激光工作台会话（缺少 &quot;format&quot;: &quot;laserwb-session&quot;）</translation>
    </message>
    <message>
        <source>%1: &quot;version&quot; must be a whole number from 1 to %2, not %3</source>
        <translation>%1：&quot;version&quot; 必须是 1 到 %2 之间的整数，而不是 %3</translation>
    </message>
    <message>
        <source>%1: session version %2 is newer than this program reads (%3)</source>
        <translation>%1：会话版本 %2 高于本程序可读取的版本（%3）</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Open session</source>
        <translation>打开会话</translation>
    </message>
    <message>
        <source>Laser Workbench sessions (*.lwb.json *.json)</source>
        <translation>激光工作台会话 (*.lwb.json *.json)</translation>
    </message>
    <message>
        <source>Cannot save the session</source>
        <translation>无法保存会话</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Save session</source>
        <translation>保存会话</translation>
    </message>
    <message>
        <source>Laser Workbench sessions (*.lwb.json)</source>
        <translation>激光工作台会话 (*.lwb.json)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>%1 has unsaved changes (verdicts, notes, edits, parameters). Save the session?</source>
        <translation>%1 有未保存的更改（判定、备注、编辑、参数）。是否保存会话？</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ModalProgress</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Working</source>
        <translation>处理中</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ParamSlider</name>
    <message>
        <source>Valid: %1</source>
        <translation>有效范围：%1</translation>
    </message>
    <message>
        <source>Slider: %1 – %2%3 (values outside are kept; the slider then sits at its end)</source>
        <translation>滑块：%1 – %2%3（超出范围的值会保留，此时滑块停在端点）</translation>
    </message>
    <message>
        <source>, logarithmic</source>
        <translation>，对数</translation>
    </message>
    <message>
        <source>%1 = %2</source>
        <translation>%1 = %2</translation>
    </message>
    <message>
        <source>Value: %1</source>
        <translation>值：%1</translation>
    </message>
</context>
<context>
    <name>lwb::ui::PlotKit</name>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg)</source>
        <translation>SVG 图形 (*.svg)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>Export the plot</source>
        <translation>导出绘图</translation>
    </message>
    <message>
        <source>Cannot export the plot</source>
        <translation>无法导出绘图</translation>
    </message>
    <message>
        <source>Reset view	Home / double-click</source>
        <translation>重置视图	Home / double-click</translation>
    </message>
    <message>
        <source>Back	Backspace</source>
        <translation>返回	Backspace</translation>
    </message>
    <message>
        <source>Box zoom (next drag)	right-drag / Shift+drag</source>
        <translation>框选缩放（下一次拖动）	right-drag / Shift+drag</translation>
    </message>
    <message>
        <source>Show all series</source>
        <translation>显示所有数据系列</translation>
    </message>
    <message>
        <source>Export as PNG…</source>
        <translation>导出为 PNG…</translation>
    </message>
    <message>
        <source>Export as SVG…</source>
        <translation>导出为 SVG…</translation>
    </message>
    <message>
        <source>Export as PDF…</source>
        <translation>导出为 PDF…</translation>
    </message>
    <message>
        <source>Copy to clipboard</source>
        <translation>复制到剪贴板</translation>
    </message>
</context>
<context>
    <name>lwb::ui::RadiometryController</name>
    <message>
        <source>Building the demo field: mosaicking 6 simulated frames…</source>
        <translation>正在构建演示场景：拼接 6 幅模拟帧…</translation>
    </message>
    <message>
        <source>Mosaicking %1 frames…</source>
        <translation>正在拼接 %1 帧…</translation>
    </message>
    <message>
        <source>demo mosaic: %1</source>
        <translation>演示拼接图：%1</translation>
    </message>
    <message>
        <source>mosaic of %1 … %2: %3</source>
        <translation>%1 … %2 的拼接图：%3</translation>
    </message>
    <message>
        <source>Demo field: %1×%2 px mosaic of 6 frames, 6 grey panels, 4 check surfaces</source>
        <translation>演示场景：6 帧拼接而成的 %1×%2 px 影像，6 块灰阶靶标，4 个检查面</translation>
    </message>
    <message>
        <source>Mosaic of %1 frames: %2×%3 px</source>
        <translation>%1 帧拼接图：%2×%3 px</translation>
    </message>
    <message>
        <source>%1: the DN image must have one channel, not %2</source>
        <translation>%1：DN 影像必须为单通道，而非 %2 通道</translation>
    </message>
    <message>
        <source>%1: %2×%3 px%4</source>
        <translation>%1：%2×%3 px%4</translation>
    </message>
    <message>
        <source>, georeferenced</source>
        <translation>，已地理配准</translation>
    </message>
    <message>
        <source>a row mosaic needs at least two frames, in scan order</source>
        <translation>行拼接至少需要两帧，且按扫描顺序排列</translation>
    </message>
    <message>
        <source>%1: frames must have one channel, not %2</source>
        <translation>%1：帧必须为单通道，而非 %2 通道</translation>
    </message>
    <message>
        <source>%1: every frame must have the depth of the first (%2)</source>
        <translation>%1：所有帧的位深必须与第一帧相同（%2）</translation>
    </message>
    <message>
        <source>%1:%2: role must be fit or check, not &quot;%3&quot;</source>
        <translation>%1:%2：role 必须为 fit 或 check，而非“%3”</translation>
    </message>
    <message>
        <source>%1:%2: region %3 has neither a rectangle nor a DN</source>
        <translation>%1:%2：区域 %3 既无矩形也无 DN</translation>
    </message>
    <message>
        <source>%1: %2 regions</source>
        <translation>%1：%2 个区域</translation>
    </message>
    <message>
        <source>region %1 (%2): needs a rectangle or a DN</source>
        <translation>区域 %1（%2）：需要矩形或 DN</translation>
    </message>
    <message>
        <source>region %1 (%2): the rectangle starts outside the image</source>
        <translation>区域 %1（%2）：矩形起点位于影像之外</translation>
    </message>
    <message>
        <source>region %1 (%2): the reflectance is not a finite number</source>
        <translation>区域 %1（%2）：反射率不是有限数值</translation>
    </message>
    <message>
        <source>panel</source>
        <translation>靶标</translation>
    </message>
    <message>
        <source>check</source>
        <translation>检查</translation>
    </message>
    <message>
        <source>no reflectance fit to export</source>
        <translation>没有可导出的反射率拟合结果</translation>
    </message>
    <message>
        <source>no relative errors to export</source>
        <translation>没有可导出的相对误差</translation>
    </message>
    <message>
        <source>no reflectance image to export (fit the line first)</source>
        <translation>没有可导出的反射率影像（请先拟合定标直线）</translation>
    </message>
    <message>
        <source>no uncertainty image to export</source>
        <translation>没有可导出的不确定度影像</translation>
    </message>
</context>
<context>
    <name>lwb::ui::RadiometryParamsPanel</name>
    <message>
        <source>Fit and uncertainty (eq. 5–6)</source>
        <translation>拟合与不确定度（式 5–6）</translation>
    </message>
    <message>
        <source>Linear DN min</source>
        <translation>线性 DN 下限</translation>
    </message>
    <message>
        <source>Linear DN max</source>
        <translation>线性 DN 上限</translation>
    </message>
    <message>
        <source>Leave regions outside the range out</source>
        <translation>排除范围外的区域</translation>
    </message>
    <message>
        <source>V_M</source>
        <translation>V_M</translation>
    </message>
    <message>
        <source>Reflectance image and check</source>
        <translation>反射率影像与检查</translation>
    </message>
    <message>
        <source>Pixels outside the range → NaN</source>
        <translation>范围外像元 → NaN</translation>
    </message>
    <message>
        <source>Per-pixel uncertainty image</source>
        <translation>逐像元不确定度影像</translation>
    </message>
    <message>
        <source>Error limit</source>
        <translation>误差限</translation>
    </message>
    <message>
        <source>Row mosaic (§3.1)</source>
        <translation>行拼接（§3.1）</translation>
    </message>
    <message>
        <source>Keypoints</source>
        <translation>特征点</translation>
    </message>
    <message>
        <source>ORB (faster)</source>
        <translation>ORB（较快）</translation>
    </message>
    <message>
        <source>AKAZE (sub-pixel)</source>
        <translation>AKAZE（亚像素）</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>运动模型</translation>
    </message>
    <message>
        <source>Translation</source>
        <translation>平移</translation>
    </message>
    <message>
        <source>Similarity</source>
        <translation>相似变换</translation>
    </message>
    <message>
        <source>Affine</source>
        <translation>仿射变换</translation>
    </message>
    <message>
        <source>Homography</source>
        <translation>单应变换</translation>
    </message>
    <message>
        <source>Blend</source>
        <translation>融合</translation>
    </message>
    <message>
        <source>Feather</source>
        <translation>羽化</translation>
    </message>
    <message>
        <source>Average</source>
        <translation>平均</translation>
    </message>
    <message>
        <source>First frame wins</source>
        <translation>首帧优先</translation>
    </message>
    <message>
        <source>RANSAC</source>
        <translation>RANSAC</translation>
    </message>
</context>
<context>
    <name>lwb::ui::RadiometryWorkspace</name>
    <message>
        <source>Calibration line (eq. 5)</source>
        <translation>定标直线（式 5）</translation>
    </message>
    <message>
        <source>Region mean V_DN</source>
        <translation>区域 DN 均值 V_DN</translation>
    </message>
    <message>
        <source>V_REF (%)</source>
        <translation>V_REF (%)</translation>
    </message>
    <message>
        <source>Paper 003 eq. 5: the measured reflectance V_REF (%) of each region against its mean DN V_DN, the fitted line V_REF = K·V_DN + B and its 1σ band</source>
        <translation>文献 003 式 5：各区域实测反射率 V_REF (%) 与其 DN 均值 V_DN 的关系、拟合直线 V_REF = K·V_DN + B 及其 1σ 带</translation>
    </message>
    <message>
        <source>Cannot mosaic the frames</source>
        <translation>无法拼接这些帧</translation>
    </message>
    <message>
        <source>Mosaicking… %1 %</source>
        <translation>正在拼接… %1 %</translation>
    </message>
    <message>
        <source>Demo</source>
        <translation>演示</translation>
    </message>
    <message>
        <source>A simulated field: six overlapping frames mosaicked, six grey panels, four check surfaces</source>
        <translation>模拟场景：六幅相互重叠的帧拼接而成，含六块灰阶靶标和四个检查面</translation>
    </message>
    <message>
        <source>DN image…</source>
        <translation>DN 影像…</translation>
    </message>
    <message>
        <source>A single-channel DN image or mosaic (TIFF, PNG, PGM; any depth)</source>
        <translation>单通道 DN 影像或拼接图（TIFF、PNG、PGM；任意位深）</translation>
    </message>
    <message>
        <source>Mosaic frames…</source>
        <translation>拼接帧…</translation>
    </message>
    <message>
        <source>The overlapping frames of one row, in scan order: stitched as radiometry mosaic does</source>
        <translation>同一行中相互重叠的帧，按扫描顺序排列：拼接方式与 radiometry mosaic 命令相同</translation>
    </message>
    <message>
        <source>Regions…</source>
        <translation>区域…</translation>
    </message>
    <message>
        <source>Fit regions CSV: name, reflectance (%), x, y, w, h (or dn) [, role fit/check]</source>
        <translation>拟合区域 CSV：name, reflectance (%), x, y, w, h（或 dn）[, role fit/check]</translation>
    </message>
    <message>
        <source>Check regions…</source>
        <translation>检查区域…</translation>
    </message>
    <message>
        <source>Check regions CSV: name, reflectance (%), x, y, w, h</source>
        <translation>检查区域 CSV：name, reflectance (%), x, y, w, h</translation>
    </message>
    <message>
        <source>Pan / zoom</source>
        <translation>平移 / 缩放</translation>
    </message>
    <message>
        <source>Draw fit region</source>
        <translation>绘制拟合区域</translation>
    </message>
    <message>
        <source>Draw check region</source>
        <translation>绘制检查区域</translation>
    </message>
    <message>
        <source>Drag a rectangle on the DN image over a grey panel, then type its measured reflectance</source>
        <translation>在 DN 影像上的灰阶靶标处拖出矩形，然后输入其实测反射率</translation>
    </message>
    <message>
        <source>Drag a rectangle over a check surface, then type its measured reflectance</source>
        <translation>在检查面上拖出矩形，然后输入其实测反射率</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Images (*.tif *.tiff *.png *.pgm);;All files (*)</source>
        <translation>影像 (*.tif *.tiff *.png *.pgm);;所有文件 (*)</translation>
    </message>
    <message>
        <source>CSV (*.csv *.txt);;All files (*)</source>
        <translation>CSV 文件 (*.csv *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Open a DN image</source>
        <translation>打开 DN 影像</translation>
    </message>
    <message>
        <source>Cannot open the image</source>
        <translation>无法打开影像</translation>
    </message>
    <message>
        <source>Frames of one row (in scan order)</source>
        <translation>同一行的帧（按扫描顺序）</translation>
    </message>
    <message>
        <source>Open fit regions</source>
        <translation>打开拟合区域</translation>
    </message>
    <message>
        <source>Open regions</source>
        <translation>打开区域</translation>
    </message>
    <message>
        <source>Cannot open the regions</source>
        <translation>无法打开区域文件</translation>
    </message>
    <message>
        <source>Open check regions</source>
        <translation>打开检查区域</translation>
    </message>
    <message>
        <source>Cannot open the check regions</source>
        <translation>无法打开检查区域文件</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>32-bit float TIFF (*.tif *.tiff)</source>
        <translation>32 位浮点 TIFF (*.tif *.tiff)</translation>
    </message>
    <message>
        <source>Reflectance image (TIFF)…</source>
        <translation>反射率影像（TIFF）…</translation>
    </message>
    <message>
        <source>Export reflectance image</source>
        <translation>导出反射率影像</translation>
    </message>
    <message>
        <source>Uncertainty image (TIFF)…</source>
        <translation>不确定度影像（TIFF）…</translation>
    </message>
    <message>
        <source>Export uncertainty image</source>
        <translation>导出不确定度影像</translation>
    </message>
    <message>
        <source>Fit K, B (CSV)…</source>
        <translation>拟合 K、B（CSV）…</translation>
    </message>
    <message>
        <source>Export fit</source>
        <translation>导出拟合结果</translation>
    </message>
    <message>
        <source>Regions with results (CSV)…</source>
        <translation>区域及结果（CSV）…</translation>
    </message>
    <message>
        <source>Export regions</source>
        <translation>导出区域</translation>
    </message>
    <message>
        <source>Relative errors (CSV)…</source>
        <translation>相对误差（CSV）…</translation>
    </message>
    <message>
        <source>Export relative errors</source>
        <translation>导出相对误差</translation>
    </message>
    <message>
        <source>DN image with the picked regions</source>
        <translation>DN 影像及所选区域</translation>
    </message>
    <message>
        <source>Column (px)</source>
        <translation>列 (px)</translation>
    </message>
    <message>
        <source>Row (px)</source>
        <translation>行 (px)</translation>
    </message>
    <message>
        <source>DN</source>
        <translation>DN</translation>
    </message>
    <message>
        <source>Reflectance image V_REF = K·V_DN + B</source>
        <translation>反射率影像 V_REF = K·V_DN + B</translation>
    </message>
    <message>
        <source>Reflectance (%)</source>
        <translation>反射率 (%)</translation>
    </message>
    <message>
        <source>Pixel (%1, %2): %3 DN</source>
        <translation>像元 (%1, %2)：%3 DN</translation>
    </message>
    <message>
        <source> · ground E %1 m, N %2 m</source>
        <translation> · 地面 E %1 m，N %2 m</translation>
    </message>
    <message>
        <source> · reflectance %1 %</source>
        <translation> · 反射率 %1 %</translation>
    </message>
    <message>
        <source> ± %1 %</source>
        <translation> ± %1 %</translation>
    </message>
    <message>
        <source>&lt;b&gt;Regions&lt;/b&gt; — type the spectrometer reflectance; drag on the DN image to add</source>
        <translation>&lt;b&gt;区域&lt;/b&gt; — 输入光谱仪测得的反射率；在 DN 影像上拖动以添加</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>Refl. %</source>
        <translation>反射率 %</translation>
    </message>
    <message>
        <source>Mean DN</source>
        <translation>DN 均值</translation>
    </message>
    <message>
        <source>Line %</source>
        <translation>直线 %</translation>
    </message>
    <message>
        <source>Resid. %</source>
        <translation>残差 %</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>Measured by the spectrometer (350–900 nm mean), %</source>
        <translation>光谱仪实测值（350–900 nm 均值），%</translation>
    </message>
    <message>
        <source>Mean DN over the rectangle (V_DN); hover for its σ</source>
        <translation>矩形内的 DN 均值（V_DN）；悬停查看其 σ</translation>
    </message>
    <message>
        <source>The fitted line at the region&apos;s mean DN: K·V_DN + B (%)</source>
        <translation>拟合直线在该区域 DN 均值处的值：K·V_DN + B (%)</translation>
    </message>
    <message>
        <source>Measured − line (%), fit regions</source>
        <translation>实测 − 直线 (%)，仅拟合区域</translation>
    </message>
    <message>
        <source>Hover a name for its rectangle (image pixels)</source>
        <translation>悬停于名称上查看其矩形（影像像素）</translation>
    </message>
    <message>
        <source>Remove region</source>
        <translation>删除区域</translation>
    </message>
    <message>
        <source>Fit ↔ check</source>
        <translation>拟合 ↔ 检查</translation>
    </message>
    <message>
        <source>Rename region</source>
        <translation>重命名区域</translation>
    </message>
    <message>
        <source>Reflectance of %1: &quot;%2&quot; is not a number</source>
        <translation>%1 的反射率：“%2”不是数值</translation>
    </message>
    <message>
        <source>Change reflectance</source>
        <translation>修改反射率</translation>
    </message>
    <message>
        <source>Change region role</source>
        <translation>修改区域类型</translation>
    </message>
    <message>
        <source>&lt;b&gt;Relative error of the check regions&lt;/b&gt; (tables 5–7)</source>
        <translation>&lt;b&gt;检查区域的相对误差&lt;/b&gt;（表 5–7）</translation>
    </message>
    <message>
        <source>Region</source>
        <translation>区域</translation>
    </message>
    <message>
        <source>Meas. %</source>
        <translation>实测 %</translation>
    </message>
    <message>
        <source>Image %</source>
        <translation>影像 %</translation>
    </message>
    <message>
        <source>Error %</source>
        <translation>误差 %</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>达标</translation>
    </message>
    <message>
        <source>Measured by the spectrometer (%)</source>
        <translation>光谱仪实测值 (%)</translation>
    </message>
    <message>
        <source>Mean of the reflectance image over the region (%)</source>
        <translation>区域内反射率影像的均值 (%)</translation>
    </message>
    <message>
        <source>|image − measured| / measured × 100</source>
        <translation>|影像 − 实测| / 实测 × 100</translation>
    </message>
    <message>
        <source>Relative error within the limit</source>
        <translation>相对误差在限值以内</translation>
    </message>
    <message>
        <source>radiometry parameters</source>
        <translation>辐射定标参数</translation>
    </message>
    <message>
        <source>View</source>
        <translation>视图</translation>
    </message>
    <message>
        <source>DN colours</source>
        <translation>DN 色表</translation>
    </message>
    <message>
        <source>Reflectance colours</source>
        <translation>反射率色表</translation>
    </message>
    <message>
        <source>Wheel: zoom (Shift: x, Ctrl: y) · drag: pan · right-drag: box zoom · double-click: whole image · right-click: export</source>
        <translation>滚轮：缩放（Shift：x，Ctrl：y）· 拖动：平移 · 右键拖动：矩形框缩放 · 双击：整幅影像 · 右键单击：导出</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>已写入 %1</translation>
    </message>
    <message>
        <source>The rectangle holds no pixel centre: drag a larger one</source>
        <translation>矩形内不含任何像元中心：请拖出更大的矩形</translation>
    </message>
    <message>
        <source>Add region</source>
        <translation>添加区域</translation>
    </message>
    <message>
        <source>The rectangle misses the image</source>
        <translation>矩形不在影像范围内</translation>
    </message>
    <message>
        <source>%1 added: type its measured reflectance (%)</source>
        <translation>已添加 %1：请输入其实测反射率 (%)</translation>
    </message>
    <message>
        <source>Move the cursor over an image for its DN and reflectance</source>
        <translation>将光标移到影像上可查看 DN 与反射率</translation>
    </message>
    <message>
        <source>simulated field, mosaic of %1 frames</source>
        <translation>模拟场景，%1 帧拼接图</translation>
    </message>
    <message>
        <source>mosaic of %1 frames (%2 … %3)</source>
        <translation>%1 帧拼接图（%2 … %3）</translation>
    </message>
    <message>
        <source>No image: open a DN image, mosaic frames, or the demo.</source>
        <translation>没有影像：请打开 DN 影像、拼接帧或演示数据。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Image&lt;/b&gt; %1 · %2×%3 px, %4-bit%5</source>
        <translation>&lt;b&gt;影像&lt;/b&gt; %1 · %2×%3 px，%4 位%5</translation>
    </message>
    <message>
        <source> · simulated line K = %1 %/DN, B = %2 %</source>
        <translation> · 模拟直线 K = %1 %/DN，B = %2 %</translation>
    </message>
    <message>
        <source>Georeferenced: pixel %1 m; top-left pixel at E %2, N %3 m; bottom-right at E %4, N %5 m</source>
        <translation>已地理配准：像元 %1 m；左上像元位于 E %2，N %3 m；右下像元位于 E %4，N %5 m</translation>
    </message>
    <message>
        <source>frames %1–%2: %3/%4 inliers, RMS %5 px&lt;br&gt;</source>
        <translation>帧 %1–%2：内点 %3/%4，RMS %5 px&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;i&gt;no mosaic&lt;/i&gt;</source>
        <translation>&lt;i&gt;未拼接&lt;/i&gt;</translation>
    </message>
    <message>
        <source>mean DN given: %1</source>
        <translation>给定的 DN 均值：%1</translation>
    </message>
    <message>
        <source>x %1, y %2, %3 × %4 px</source>
        <translation>x %1，y %2，%3 × %4 px</translation>
    </message>
    <message>
        <source>fit</source>
        <translation>拟合</translation>
    </message>
    <message>
        <source>check</source>
        <translation>检查</translation>
    </message>
    <message>
        <source>Type the measured reflectance (%)</source>
        <translation>输入实测反射率 (%)</translation>
    </message>
    <message>
        <source>σ %1 DN over %2 pixels%3</source>
        <translation>σ %1 DN，共 %2 个像元%3</translation>
    </message>
    <message>
        <source>, %1 outside the linear range</source>
        <translation>，%1 个超出线性范围</translation>
    </message>
    <message>
        <source>±1σ (incl. V_M)</source>
        <translation>±1σ（含 V_M）</translation>
    </message>
    <message>
        <source>K·V_DN + B</source>
        <translation>K·V_DN + B</translation>
    </message>
    <message>
        <source>fit regions (%1)</source>
        <translation>拟合区域（%1）</translation>
    </message>
    <message>
        <source>left out (range)</source>
        <translation>已排除（范围外）</translation>
    </message>
    <message>
        <source>check (not fitted)</source>
        <translation>检查（不参与拟合）</translation>
    </message>
    <message>
        <source>&lt;b&gt;K&lt;/b&gt; = %1 ± %2 %/DN&lt;br&gt;&lt;b&gt;B&lt;/b&gt; = %3 ± %4 %&lt;br&gt;%5 regions · R² %6 · s %7 % · cov(K,B) %8&lt;br&gt;&lt;b&gt;Uncertainty&lt;/b&gt; (eq. 6) %9 % · at the mean DN %10: %11 %</source>
        <translation>&lt;b&gt;K&lt;/b&gt; = %1 ± %2 %/DN&lt;br&gt;&lt;b&gt;B&lt;/b&gt; = %3 ± %4 %&lt;br&gt;%5 个区域 · R² %6 · s %7 % · cov(K,B) %8&lt;br&gt;&lt;b&gt;不确定度&lt;/b&gt;（式 6）%9 % · DN 均值 %10 处：%11 %</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;span style=&apos;color:#2c8c2c&apos;&gt;Simulated line: K %1 (fit − sim %2σ), B %3 (%4σ)&lt;/span&gt;</source>
        <translation>&lt;br&gt;&lt;span style=&apos;color:#2c8c2c&apos;&gt;模拟直线：K %1（拟合 − 模拟 %2σ），B %3（%4σ）&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;No fit:&lt;/b&gt; %1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;无拟合结果：&lt;/b&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#666&apos;&gt;%1&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#666&apos;&gt;%1&lt;/span&gt;</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>NO</source>
        <translation>否</translation>
    </message>
    <message>
        <source>max %1 %, mean %2 % (limit %3 %): %4</source>
        <translation>最大 %1 %，平均 %2 %（限值 %3 %）：%4</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#1e7832&apos;&gt;&lt;b&gt;all within&lt;/b&gt;&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#1e7832&apos;&gt;&lt;b&gt;全部达标&lt;/b&gt;&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;limit exceeded&lt;/b&gt;&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c0392b&apos;&gt;&lt;b&gt;超出限值&lt;/b&gt;&lt;/span&gt;</translation>
    </message>
    <message>
        <source>radiometry region %1: role must be fit or check, not &quot;%2&quot;</source>
        <translation>辐射定标区域 %1：role 必须为 fit 或 check，而非“%2”</translation>
    </message>
    <message>
        <source>radiometry region %1 (%2): reflectance must be a number or null</source>
        <translation>辐射定标区域 %1（%2）：reflectance 必须为数值或 null</translation>
    </message>
    <message>
        <source>radiometry region %1 (%2): rect must be [x, y, w, h], whole numbers with 0 ≤ x, y ≤ 1000000 and 1 ≤ w, h ≤ 1000000</source>
        <translation>辐射定标区域 %1（%2）：rect 必须为 [x, y, w, h]，取整数，且 0 ≤ x, y ≤ 1000000、1 ≤ w, h ≤ 1000000</translation>
    </message>
    <message>
        <source>radiometry region %1 (%2): needs a rect or a dn</source>
        <translation>辐射定标区域 %1（%2）：需要 rect 或 dn</translation>
    </message>
    <message>
        <source>radiometry view: colour map out of range</source>
        <translation>辐射定标视图：色表超出范围</translation>
    </message>
    <message>
        <source>radiometry frames: a mosaic needs at least two frames</source>
        <translation>辐射定标帧：拼接至少需要两帧</translation>
    </message>
    <message>
        <source>%1: a folder of frames; open them with Mosaic frames…</source>
        <translation>%1：这是一个帧文件夹，请用“拼接帧…”打开</translation>
    </message>
    <message>
        <source>Radiometry</source>
        <translation>辐射定标</translation>
    </message>
    <message>
        <source>a synthetic radiometric scene</source>
        <translation>一个合成辐射场景</translation>
    </message>
</context>
<context>
    <name>lwb::ui::RangeEdit</name>
    <message>
        <source>   min</source>
        <translation>   最小</translation>
    </message>
    <message>
        <source>   max</source>
        <translation>   最大</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SchemaForm</name>
    <message>
        <source>true or false</source>
        <translation>真或假</translation>
    </message>
</context>
<context>
    <name>lwb::ui::ShotTableModel</name>
    <message>
        <source>File</source>
        <translation>文件</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Beam</source>
        <translation>波束</translation>
    </message>
    <message>
        <source>X (px)</source>
        <translation>X (px)</translation>
    </message>
    <message>
        <source>Y (px)</source>
        <translation>Y (px)</translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <source>Failed criteria</source>
        <translation>未通过的准则</translation>
    </message>
    <message>
        <source>Noise</source>
        <translation>噪声</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>备注</translation>
    </message>
    <message>
        <source> (manual)</source>
        <translation>（人工）</translation>
    </message>
    <message>
        <source>good</source>
        <translation>合格</translation>
    </message>
    <message>
        <source>doubtful</source>
        <translation>存疑</translation>
    </message>
    <message>
        <source>rejected</source>
        <translation>剔除</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrAllPassesDialog</name>
    <message>
        <source>All passes of %1</source>
        <translation>%1 的全部过境</translation>
    </message>
    <message>
        <source>The command&apos;s defaults and the saved preset of each satellite (%1), as laserwb-cli slr --all-passes --preset.</source>
        <translation>命令的默认参数加上各卫星已保存的预设（%1），与 laserwb-cli slr --all-passes --preset 相同。</translation>
    </message>
    <message>
        <source>The command&apos;s defaults (no saved presets), as laserwb-cli slr --all-passes.</source>
        <translation>命令的默认参数（不使用已保存的预设），与 laserwb-cli slr --all-passes 相同。</translation>
    </message>
    <message>
        <source>Double-click a screened row (or select it and press Open) to open that pass in the workspace</source>
        <translation>双击已筛选的行（或选中后按“打开过境”）即可在工作区中打开该过境</translation>
    </message>
    <message>
        <source>Blocks decided so far</source>
        <translation>已判定的数据块</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Stop after the passes under way; the blocks not reached are marked cancelled</source>
        <translation>处理完正在进行的过境后停止；未处理到的数据块标记为已取消</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <source>Write the table as summary.csv (laserwb-cli slr --all-passes writes the same bytes)</source>
        <translation>将表格写为 summary.csv（与 laserwb-cli slr --all-passes 写出的字节完全相同）</translation>
    </message>
    <message>
        <source>Export products…</source>
        <translation>导出产品…</translation>
    </message>
    <message>
        <source>Write the day&apos;s products into a folder, as laserwb-cli slr --all-passes --out-dir: passNNN.csv/.frd/.npt, normal_points.npt, summary.csv, provenance.json</source>
        <translation>将当日产品写入文件夹，与 laserwb-cli slr --all-passes --out-dir 相同：passNNN.csv/.frd/.npt、normal_points.npt、summary.csv、provenance.json</translation>
    </message>
    <message>
        <source>Open pass</source>
        <translation>打开过境</translation>
    </message>
    <message>
        <source>Open the selected pass in the SLR workspace</source>
        <translation>在 SLR 工作区中打开所选过境</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>Close the table (a screening under way is cancelled)</source>
        <translation>关闭表格（正在进行的筛选将被取消）</translation>
    </message>
    <message>
        <source>Screening %1 blocks…</source>
        <translation>正在筛选 %1 个数据块…</translation>
    </message>
    <message>
        <source>Export the table</source>
        <translation>导出表格</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export the day&apos;s products into a folder</source>
        <translation>将当日产品导出到文件夹</translation>
    </message>
    <message>
        <source>Cancelling after the passes under way…</source>
        <translation>正在取消，等待进行中的过境处理完毕…</translation>
    </message>
    <message>
        <source>the screening is still under way: export when it has finished</source>
        <translation>筛选仍在进行：请在完成后再导出</translation>
    </message>
    <message>
        <source>Writing the day&apos;s products into %1…</source>
        <translation>正在将当日产品写入 %1…</translation>
    </message>
    <message>
        <source>%1 of %2 blocks decided (%3 failed)</source>
        <translation>%2 个数据块中已判定 %1 个（%3 个失败）</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>not run</source>
        <translation>未运行</translation>
    </message>
    <message>
        <source>Wrote %1 files into %2</source>
        <translation>已将 %1 个文件写入 %2</translation>
    </message>
    <message>
        <source>Products not written: %1</source>
        <translation>未写出产品：%1</translation>
    </message>
    <message>
        <source>Cancelled: %1 of %2 blocks decided (%3 failed)</source>
        <translation>已取消：%2 个数据块中已判定 %1 个（%3 个失败）</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>已停止：%1</translation>
    </message>
    <message>
        <source>%1 blocks: %2 screened, %3 doubtful, %4 failed, %5 station normal points, %6 skipped</source>
        <translation>%1 个数据块：%2 个已筛选，%3 个存疑，%4 个失败，%5 个为测站标准点，%6 个跳过</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrController</name>
    <message>
        <source>screening: %1</source>
        <translation>筛选：%1</translation>
    </message>
    <message>
        <source>no CRD file is open</source>
        <translation>未打开 CRD 文件</translation>
    </message>
    <message>
        <source>Pass %1 cannot be processed: %2</source>
        <translation>过境 %1 无法处理：%2</translation>
    </message>
    <message>
        <source>%1: %2 points, O-C from %3%4</source>
        <translation>%1：%2 个点，O-C 取自 %3%4</translation>
    </message>
    <message>
        <source>; preset of %1 applied</source>
        <translation>；已应用 %1 的预设</translation>
    </message>
    <message>
        <source>the pass names no satellite (H3 record) to key a preset on</source>
        <translation>该过境未注明卫星（H3 记录），无法据此选用预设</translation>
    </message>
    <message>
        <source>Presets not read: %1</source>
        <translation>未能读取预设：%1</translation>
    </message>
    <message>
        <source>no screening result to export</source>
        <translation>没有可导出的筛选结果</translation>
    </message>
    <message>
        <source>the simulation&apos;s truth</source>
        <translation>模拟真值</translation>
    </message>
    <message>
        <source>the station&apos;s filter flags</source>
        <translation>测站的筛选标记</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrFileCheckDialog</name>
    <message>
        <source>CRD file check</source>
        <translation>CRD 文件检查</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>行</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>严重程度</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>记录</translation>
    </message>
    <message>
        <source>Rule</source>
        <translation>规则</translation>
    </message>
    <message>
        <source>Reason</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>The rule of the CRD specification it breaks (docs/crd-check.md)</source>
        <translation>所违反的 CRD 规范规则（docs/crd-check.md）</translation>
    </message>
    <message>
        <source>file</source>
        <translation>文件</translation>
    </message>
    <message numerus="yes">
        <source> (%n like it)</source>
        <translation>
            <numerusform>（另有 %n 处同类）</numerusform>
        </translation>
    </message>
    <message>
        <source>error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Copy as text</source>
        <translation>复制为文本</translation>
    </message>
    <message>
        <source>The list as laserwb-cli crd check prints it, a line per problem</source>
        <translation>按 laserwb-cli crd check 的输出格式复制列表，每个问题一行</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrParamsPanel</name>
    <message>
        <source>Screening (binary image)</source>
        <translation>筛选（二值图像）</translation>
    </message>
    <message>
        <source>Automatic scale, area limit and connectivity</source>
        <translation>自动确定尺度、面积阈值和连通性</translation>
    </message>
    <message>
        <source>mag_T</source>
        <translation>mag_T</translation>
    </message>
    <message>
        <source>mag_OC</source>
        <translation>mag_OC</translation>
    </message>
    <message>
        <source>Area limit</source>
        <translation>面积阈值</translation>
    </message>
    <message>
        <source>Connectivity</source>
        <translation>连通性</translation>
    </message>
    <message>
        <source>4-connectivity</source>
        <translation>4 连通</translation>
    </message>
    <message>
        <source>8-connectivity</source>
        <translation>8 连通</translation>
    </message>
    <message>
        <source>Cosine C</source>
        <translation>余弦常数 C</translation>
    </message>
    <message>
        <source>Post-fit and normal points</source>
        <translation>后拟合与标准点</translation>
    </message>
    <message>
        <source>Rejection (k σ)</source>
        <translation>剔除（k σ）</translation>
    </message>
    <message>
        <source>Trend degree ≤</source>
        <translation>趋势阶数 ≤</translation>
    </message>
    <message>
        <source>Advanced (every other parameter)</source>
        <translation>高级（其余全部参数）</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrStationNpPanel</name>
    <message>
        <source>Station normal points…</source>
        <translation>测站标准点…</translation>
    </message>
    <message>
        <source>Open the station&apos;s CRD normal-point file (.npt) for this pass: its normal points are drawn over ours and the differences listed here</source>
        <translation>打开该过境的测站 CRD 标准点文件（.npt）：其标准点叠加绘制在我方标准点之上，差值列于此处</translation>
    </message>
    <message>
        <source>no station file</source>
        <translation>无测站文件</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>Stop comparing with the station&apos;s normal points</source>
        <translation>停止与测站标准点比较</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <source>The table of differences as CSV</source>
        <translation>以 CSV 格式导出差值表</translation>
    </message>
    <message>
        <source>UTC</source>
        <translation>UTC</translation>
    </message>
    <message>
        <source>Bin</source>
        <translation>分段</translation>
    </message>
    <message>
        <source>Δ (mm)</source>
        <translation>Δ (mm)</translation>
    </message>
    <message>
        <source>Station N</source>
        <translation>测站 N</translation>
    </message>
    <message>
        <source>Our N</source>
        <translation>我方 N</translation>
    </message>
    <message>
        <source>Station RMS (ps)</source>
        <translation>测站 RMS (ps)</translation>
    </message>
    <message>
        <source>Our RMS (ps)</source>
        <translation>我方 RMS (ps)</translation>
    </message>
    <message>
        <source>Ranges in the station&apos;s normal point</source>
        <translation>测站标准点所含测距值个数</translation>
    </message>
    <message>
        <source>Ranges in our normal point</source>
        <translation>我方标准点所含测距值个数</translation>
    </message>
    <message>
        <source>Ours − station: our normal point less the station&apos;s, one-way range (mm), at the station&apos;s epoch (ours moved along our post-fit trend)</source>
        <translation>我方 − 测站：我方标准点减去测站标准点，单程测距值（mm），取测站历元（我方标准点沿我方后拟合趋势移至该历元）</translation>
    </message>
    <message>
        <source>Both in this bin, or only one of the two</source>
        <translation>两者均在此分段内，或仅有其一</translation>
    </message>
    <message>
        <source>Export the differences</source>
        <translation>导出差值</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>%1: no post-fit of the pass yet, so no normal points of ours</source>
        <translation>%1：该过境尚未进行后拟合，因此没有我方标准点</translation>
    </message>
    <message>
        <source>Open the station&apos;s normal points of this pass to see them over ours, bin by bin.</source>
        <translation>打开该过境的测站标准点，逐个分段与我方标准点叠加比较。</translation>
    </message>
    <message>
        <source>%1, %2 (block %3): %4</source>
        <translation>%1，%2（数据块 %3）：%4</translation>
    </message>
    <message>
        <source>both</source>
        <translation>两者</translation>
    </message>
    <message>
        <source>station only</source>
        <translation>仅测站</translation>
    </message>
    <message>
        <source>ours only</source>
        <translation>仅我方</translation>
    </message>
    <message>
        <source>Nothing to export: %1</source>
        <translation>无可导出内容：%1</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrStrips</name>
    <message>
        <source>No strip on a pass of %1 points (strips are computed up to %2: each is the pass run again %3 times)</source>
        <translation>%1 个点的过境不画条带（条带只对不超过 %2 个点的过境计算：每条需将过境重新运行 %3 次）</translation>
    </message>
    <message>
        <source>Strip: points kept along the slider (up to %1)</source>
        <translation>条带：沿滑块各处保留的点数（最多 %1）</translation>
    </message>
    <message>
        <source>; post-fit RMS %1 ps all along</source>
        <translation>；后拟合 RMS 各处均为 %1 ps</translation>
    </message>
    <message>
        <source>; post-fit RMS %1 to %2 ps</source>
        <translation>；后拟合 RMS %1 至 %2 ps</translation>
    </message>
    <message>
        <source>; orange: F1 against %1, %2 all along</source>
        <translation>；橙线：相对%1的 F1，各处均为 %2</translation>
    </message>
    <message>
        <source>; orange: F1 against %1, %2 to %3 (best at %4)</source>
        <translation>；橙线：相对%1的 F1，%2 至 %3（最佳在 %4）</translation>
    </message>
    <message>
        <source>; orange: the RMS (no labels: the pass has no station flags)</source>
        <translation>；橙线：RMS（无标签：该过境没有测站标记）</translation>
    </message>
    <message>
        <source>; %1 of the %2 values give no run</source>
        <translation>；%2 个取值中有 %1 个无法运行</translation>
    </message>
</context>
<context>
    <name>lwb::ui::SlrWorkspace</name>
    <message>
        <source>CRD file check</source>
        <translation>CRD 文件检查</translation>
    </message>
    <message>
        <source>Open a CRD file first: the pass shown is not from one.</source>
        <translation>请先打开 CRD 文件：当前显示的过境并非来自 CRD 文件。</translation>
    </message>
    <message>
        <source>Checking %1…</source>
        <translation>正在检查 %1…</translation>
    </message>
    <message>
        <source>Check the CRD file…</source>
        <translation>检查 CRD 文件…</translation>
    </message>
    <message>
        <source>Every record of the open CRD file against the CRD format, as laserwb-cli crd check lists them</source>
        <translation>按 CRD 格式检查已打开 CRD 文件的每条记录，与 laserwb-cli crd check 列出的结果相同</translation>
    </message>
    <message>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <source>%1: opening cancelled; the pass shown before stays</source>
        <translation>%1：已取消打开；仍显示之前的过境</translation>
    </message>
    <message>
        <source>Opening %1 cancelled</source>
        <translation>已取消打开 %1</translation>
    </message>
    <message>
        <source>Opening pass %1…</source>
        <translation>正在打开过境 %1…</translation>
    </message>
    <message>
        <source>Opening pass %1 cancelled</source>
        <translation>已取消打开过境 %1</translation>
    </message>
    <message>
        <source>Open CRD / O-C CSV…</source>
        <translation>打开 CRD / O-C CSV…</translation>
    </message>
    <message>
        <source>Open an ILRS CRD full-rate file (every pass is listed) or an O-C table (CSV: epoch_s,oc_s)</source>
        <translation>打开 ILRS CRD 全速率文件（列出其中所有过境）或 O-C 表（CSV：epoch_s,oc_s）</translation>
    </message>
    <message>
        <source>CPF…</source>
        <translation>CPF…</translation>
    </message>
    <message>
        <source>A CPF prediction file: with the SINEX file, O-C from the prediction (replaces the one given)</source>
        <translation>CPF 预报文件：配合 SINEX 文件，由预报计算 O-C（替换文件中给出的 O-C）</translation>
    </message>
    <message>
        <source>CPF folder…</source>
        <translation>CPF 文件夹…</translation>
    </message>
    <message>
        <source>A folder of CPF files: for each pass the one whose satellite and time span fit is picked</source>
        <translation>CPF 文件所在的文件夹：为每个过境选取卫星与时间跨度相符的文件</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>Clear the prediction: O-C from each pass&apos;s own fitted TOF trend</source>
        <translation>清除预报：O-C 改由各过境自身拟合的飞行时间趋势求得</translation>
    </message>
    <message>
        <source>SINEX…</source>
        <translation>SINEX…</translation>
    </message>
    <message>
        <source>SINEX station coordinates (needed with the CPF for O-C from the prediction, and for day/night normal points)</source>
        <translation>SINEX 测站坐标（与 CPF 配合由预报计算 O-C 时需要，计算昼夜标准点时也需要）</translation>
    </message>
    <message>
        <source>Clear the station coordinates</source>
        <translation>清除测站坐标</translation>
    </message>
    <message>
        <source>no prediction</source>
        <translation>无预报</translation>
    </message>
    <message>
        <source>The prediction in use</source>
        <translation>当前使用的预报</translation>
    </message>
    <message>
        <source>no station file</source>
        <translation>无测站文件</translation>
    </message>
    <message>
        <source>The station coordinates in use</source>
        <translation>当前使用的测站坐标</translation>
    </message>
    <message>
        <source>Folder of CPF predictions</source>
        <translation>CPF 预报文件夹</translation>
    </message>
    <message>
        <source>CPF prediction</source>
        <translation>CPF 预报</translation>
    </message>
    <message>
        <source>CPF (*.hts *.cpf *.sgf);;All files (*)</source>
        <translation>CPF 文件 (*.hts *.cpf *.sgf);;所有文件 (*)</translation>
    </message>
    <message>
        <source>SINEX station coordinates</source>
        <translation>SINEX 测站坐标</translation>
    </message>
    <message>
        <source>SINEX (*.snx *.SNX);;All files (*)</source>
        <translation>SINEX 文件 (*.snx *.SNX);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot use the file</source>
        <translation>无法使用该文件</translation>
    </message>
    <message>
        <source>CPF</source>
        <translation>CPF</translation>
    </message>
    <message>
        <source>SINEX</source>
        <translation>SINEX</translation>
    </message>
    <message>
        <source>Epoch (s since 0h UTC)</source>
        <translation>历元（自 UTC 0 时起的秒数）</translation>
    </message>
    <message>
        <source>O-C (ns, two-way)</source>
        <translation>O-C（ns，双程）</translation>
    </message>
    <message>
        <source>Binary image: pixels by region class</source>
        <translation>二值图像：按区域类别显示像素</translation>
    </message>
    <message>
        <source>O-C</source>
        <translation>O-C</translation>
    </message>
    <message>
        <source>mm, one-way</source>
        <translation>mm，单程</translation>
    </message>
    <message>
        <source>Post-fit residual (ps, two-way)</source>
        <translation>后拟合残差（ps，双程）</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>点数</translation>
    </message>
    <message>
        <source>Post-fit residuals of the kept points, ps two-way (1 ps = 0.15 mm one-way)</source>
        <translation>保留点的后拟合残差，ps，双程（1 ps = 0.15 mm 单程）</translation>
    </message>
    <message>
        <source>empty</source>
        <translation>空</translation>
    </message>
    <message>
        <source>noise regions</source>
        <translation>噪声区域</translation>
    </message>
    <message>
        <source>recovered regions</source>
        <translation>恢复区域</translation>
    </message>
    <message>
        <source>signal regions</source>
        <translation>信号区域</translation>
    </message>
    <message>
        <source>Every pass of the file by start time: station, satellite, UTC start, duration, points, status</source>
        <translation>文件中按开始时间排列的全部过境：测站、卫星、UTC 开始时间、时长、点数、状态</translation>
    </message>
    <message>
        <source>Screen all passes…</source>
        <translation>筛选全部过境…</translation>
    </message>
    <message>
        <source>Screen every pass of the file in the background: a table of the results, any row opens its pass</source>
        <translation>在后台筛选文件中的每个过境：生成结果表，任一行均可打开对应过境</translation>
    </message>
    <message>
        <source>Residual (O-C − trend)</source>
        <translation>残差（O-C − 趋势）</translation>
    </message>
    <message>
        <source>Main plot: the O-C (ns, two-way), or the residual about the post-fit trend (ps two-way, mm one-way on the right axis) where the track&apos;s spread is visible</source>
        <translation>主图：O-C（ns，双程），或相对后拟合趋势的残差（ps，双程；右侧坐标轴为单程 mm），残差视图中可看清轨迹的离散程度</translation>
    </message>
    <message>
        <source>Seconds of day</source>
        <translation>日内秒</translation>
    </message>
    <message>
        <source>Time axis in seconds since 0h UTC instead of hh:mm:ss</source>
        <translation>时间轴以自 UTC 0 时起的秒数显示，而非 hh:mm:ss</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>复位</translation>
    </message>
    <message>
        <source>Fit every plot to its data again (also: double-click a plot)</source>
        <translation>重新将每幅图缩放至适合其数据（也可双击图）</translation>
    </message>
    <message>
        <source>The point nearest the mouse on the main plot: UTC epoch, O-C, residual, class, record index</source>
        <translation>主图上离鼠标最近的点：UTC 历元、O-C、残差、类别、记录序号</translation>
    </message>
    <message>
        <source>Pass:</source>
        <translation>过境:</translation>
    </message>
    <message>
        <source>Main plot:</source>
        <translation>主图:</translation>
    </message>
    <message>
        <source>Residual histogram</source>
        <translation>残差直方图</translation>
    </message>
    <message>
        <source>Station normal points</source>
        <translation>测站标准点</translation>
    </message>
    <message>
        <source>Open the station&apos;s CRD normal points of the pass: drawn over ours, differences bin by bin</source>
        <translation>打开该过境的测站 CRD 标准点：叠加绘制在我方标准点之上，逐个分段列出差值</translation>
    </message>
    <message>
        <source>Screen all passes</source>
        <translation>筛选全部过境</translation>
    </message>
    <message>
        <source>Open a CRD file first.</source>
        <translation>请先打开 CRD 文件。</translation>
    </message>
    <message>
        <source>The station&apos;s normal points</source>
        <translation>测站标准点</translation>
    </message>
    <message>
        <source>CRD normal points (*.npt *.np2 *.crd);;All files (*)</source>
        <translation>CRD 标准点文件 (*.npt *.np2 *.crd);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Mouse on the main plot</source>
        <translation>主图上的鼠标操作</translation>
    </message>
    <message>
        <source>Pan / zoom</source>
        <translation>平移 / 缩放</translation>
    </message>
    <message>
        <source>Drag pans, the wheel zooms both axes; Shift+wheel zooms time only, Ctrl+wheel O-C only; right-drag zooms to a box, Backspace steps back</source>
        <translation>拖动平移，滚轮同时缩放两轴；Shift+滚轮仅缩放时间轴，Ctrl+滚轮仅缩放 O-C 轴；右键拖动缩放至矩形框，Backspace 后退一步</translation>
    </message>
    <message>
        <source>Box zoom</source>
        <translation>框选缩放</translation>
    </message>
    <message>
        <source>Drag a box to zoom to it (the linked binary image follows); Home or double-click resets</source>
        <translation>拖出矩形框即缩放至该框（联动的二值图像随之变化）；按 Home 键或双击可复位</translation>
    </message>
    <message>
        <source>Box forces points in</source>
        <translation>矩形框强制纳入点</translation>
    </message>
    <message>
        <source>Points in the box are accepted whatever the screening says (undo: Edit ▸ Undo)</source>
        <translation>矩形框内的点一律接受，不论筛选结果如何（撤销：编辑 ▸ 撤销）</translation>
    </message>
    <message>
        <source>Box forces points out</source>
        <translation>矩形框强制剔除点</translation>
    </message>
    <message>
        <source>Points in the box are rejected whatever the screening says (undo: Edit ▸ Undo)</source>
        <translation>矩形框内的点一律剔除，不论筛选结果如何（撤销：编辑 ▸ 撤销）</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Undo the last edit or parameter change (the workbench&apos;s undo history, Ctrl+Z)</source>
        <translation>撤销上一次编辑或参数更改（工作台的撤销历史，Ctrl+Z）</translation>
    </message>
    <message>
        <source>Clear edits</source>
        <translation>清除编辑</translation>
    </message>
    <message>
        <source>Drop every manual edit of the pass (undoable)</source>
        <translation>删除该过境的全部人工编辑（可撤销）</translation>
    </message>
    <message>
        <source>Presets and export</source>
        <translation>预设与导出</translation>
    </message>
    <message>
        <source>Save as this satellite&apos;s preset</source>
        <translation>保存为该卫星的预设</translation>
    </message>
    <message>
        <source>Export points (CSV)…</source>
        <translation>导出点（CSV）…</translation>
    </message>
    <message>
        <source>Export CRD full rate with flags…</source>
        <translation>导出带标志的 CRD 全速率数据…</translation>
    </message>
    <message>
        <source>Export normal points (CRD)…</source>
        <translation>导出标准点（CRD）…</translation>
    </message>
    <message>
        <source>Keep the current parameters (and the scale used) for the passes of this satellite</source>
        <translation>为该卫星的过境保留当前参数（及所用尺度）</translation>
    </message>
    <message>
        <source>Per point: index, epoch, O-C, class, region, residual, kept, station flag</source>
        <translation>每个点：序号、历元、O-C、类别、区域、残差、是否保留、测站标志</translation>
    </message>
    <message>
        <source>CRD full rate with filter flags 2 (accepted) / 1 (noise): this pass only, or the whole file with this pass&apos;s flags set</source>
        <translation>带滤波标志 2（接受）/ 1（噪声）的 CRD 全速率数据：仅含该过境，或整个文件并设置该过境的标志</translation>
    </message>
    <message>
        <source>The normal points of the pass as a CRD normal-point file</source>
        <translation>该过境的标准点，存为 CRD 标准点文件</translation>
    </message>
    <message>
        <source>Clear SLR edits</source>
        <translation>清除 SLR 编辑</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>预设</translation>
    </message>
    <message>
        <source>Preset saved for %1 in %2</source>
        <translation>已在 %2 中保存 %1 的预设</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>已写出 %1</translation>
    </message>
    <message>
        <source>Export points</source>
        <translation>导出点</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export CRD full rate</source>
        <translation>导出 CRD 全速率数据</translation>
    </message>
    <message>
        <source>This pass is not from a CRD file (%1): there are no CRD records to flag. Export its points as CSV, or its normal points as CRD.</source>
        <translation>该过境并非来自 CRD 文件（%1）：没有可设置标志的 CRD 记录。可将其点导出为 CSV，或将其标准点导出为 CRD。</translation>
    </message>
    <message>
        <source>a simulation</source>
        <translation>模拟数据</translation>
    </message>
    <message>
        <source>Write which records?</source>
        <translation>写出哪些记录？</translation>
    </message>
    <message>
        <source>Pass %1 of %2 passes in %3. Its records get filter flag 2 (accepted) or 1 (noise).</source>
        <translation>%3 中共有 %2 个过境，此为第 %1 个。其记录的滤波标志将设为 2（接受）或 1（噪声）。</translation>
    </message>
    <message>
        <source>This pass only</source>
        <translation>仅该过境</translation>
    </message>
    <message>
        <source>Whole file with this pass&apos;s flags set</source>
        <translation>整个文件，并设置该过境的标志</translation>
    </message>
    <message>
        <source>CRD (*.frd *.fr2 *.crd)</source>
        <translation>CRD 文件 (*.frd *.fr2 *.crd)</translation>
    </message>
    <message>
        <source>Export normal points</source>
        <translation>导出标准点</translation>
    </message>
    <message>
        <source>CRD (*.npt *.np2 *.crd)</source>
        <translation>CRD 文件 (*.npt *.np2 *.crd)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Screening failed:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;筛选失败：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>Nothing written: %1</source>
        <translation>未写出任何内容：%1</translation>
    </message>
    <message>
        <source>pass %1 (%2, %3): %4 of %5 screened records flagged 2 (data), the rest 1 (noise)</source>
        <translation>过境 %1（%2，%3）：%5 条已筛选记录中 %4 条标记为 2（数据），其余标记为 1（噪声）</translation>
    </message>
    <message>
        <source>Wrote %1: the whole file (%2 passes), %3; the other passes as read</source>
        <translation>已写出 %1：整个文件（%2 个过境），%3；其他过境保持原样</translation>
    </message>
    <message>
        <source>Wrote %1: this pass only, %2</source>
        <translation>已写出 %1：仅该过境，%2</translation>
    </message>
    <message>
        <source>The prediction in use: none</source>
        <translation>当前使用的预报：无</translation>
    </message>
    <message>
        <source>The station coordinates in use: none</source>
        <translation>当前使用的测站坐标：无</translation>
    </message>
    <message>
        <source>O-C table, %1 points</source>
        <translation>O-C 表，%1 个点</translation>
    </message>
    <message>
        <source>cannot be processed: %1</source>
        <translation>无法处理：%1</translation>
    </message>
    <message>
        <source>%1. %2 · %3 · %4 · %5 · %6 pts</source>
        <translation>%1. %2 · %3 · %4 · %5 · %6 点</translation>
    </message>
    <message>
        <source>&lt;b style=&quot;color:#b00000&quot;&gt;Pass %1 cannot be processed:&lt;/b&gt; %2&lt;br&gt;The other passes of the file can be chosen in the list.</source>
        <translation>&lt;b style=&quot;color:#b00000&quot;&gt;过境 %1 无法处理：&lt;/b&gt;%2&lt;br&gt;可在列表中选择该文件的其他过境。</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt; %2 — %3 points, O-C from %4%5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt; %2 — %3 个点，O-C 取自 %4%5</translation>
    </message>
    <message>
        <source>, station %1</source>
        <translation>，测站 %1</translation>
    </message>
    <message>
        <source>; &lt;b&gt;preset %1&lt;/b&gt; applied (%2)</source>
        <translation>；已应用&lt;b&gt;预设 %1&lt;/b&gt;（%2）</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b style=&quot;color:#a05000&quot;&gt;Prediction not used:&lt;/b&gt; %1</source>
        <translation>&lt;br&gt;&lt;b style=&quot;color:#a05000&quot;&gt;未使用预报：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b style=&quot;color:#b00000&quot;&gt;Damaged records: exports are refused.&lt;/b&gt; %1</source>
        <translation>&lt;br&gt;&lt;b style=&quot;color:#b00000&quot;&gt;记录已损坏：拒绝导出。&lt;/b&gt;%1</translation>
    </message>
    <message numerus="yes">
        <source>&lt;br&gt;&lt;b&gt;%n warning(s) reading the files:&lt;/b&gt;</source>
        <translation>
            <numerusform>&lt;br&gt;&lt;b&gt;读取文件时出现 %n 条警告：&lt;/b&gt;</numerusform>
        </translation>
    </message>
    <message>
        <source>&lt;br&gt;… and %1 more (in the status messages)</source>
        <translation>&lt;br&gt;… 另有 %1 条（见状态栏消息）</translation>
    </message>
    <message>
        <source>Simulated kHz pass (10 % signal)</source>
        <translation>模拟 kHz 过境（10 % 信号）</translation>
    </message>
    <message>
        <source>Simulated kHz pass</source>
        <translation>模拟 kHz 过境</translation>
    </message>
    <message numerus="yes">
        <source>Force %n SLR point(s) in</source>
        <translation>
            <numerusform>强制纳入 %n 个 SLR 点</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Force %n SLR point(s) out</source>
        <translation>
            <numerusform>强制剔除 %n 个 SLR 点</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 points forced %2 (Edit ▸ Undo takes it back)</source>
        <translation>%1 个点已强制%2（编辑 ▸ 撤销可还原）</translation>
    </message>
    <message>
        <source>in</source>
        <translation>纳入</translation>
    </message>
    <message>
        <source>out</source>
        <translation>剔除</translation>
    </message>
    <message>
        <source>Epoch (s)</source>
        <translation>历元 (s)</translation>
    </message>
    <message>
        <source>UTC on %1 (hh:mm:ss)</source>
        <translation>%1 UTC（hh:mm:ss）</translation>
    </message>
    <message>
        <source>Seconds of day (UTC %1)</source>
        <translation>日内秒（UTC %1）</translation>
    </message>
    <message>
        <source>%1 · %2 %3 %4
%5</source>
        <translation>%1 · %2 %3 %4
%5</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>残差</translation>
    </message>
    <message>
        <source>image</source>
        <translation>图像</translation>
    </message>
    <message>
        <source>ps</source>
        <translation>ps</translation>
    </message>
    <message>
        <source>ns</source>
        <translation>ns</translation>
    </message>
    <message>
        <source>The point nearest the mouse on the O-C plot or the binary image: UTC epoch, O-C, residual, class, record index</source>
        <translation>O-C 图或二值图像上离鼠标最近的点：UTC 历元、O-C、残差、类别、记录序号</translation>
    </message>
    <message>
        <source>%1 · O-C %2 ns</source>
        <translation>%1 · O-C %2 ns</translation>
    </message>
    <message>
        <source> · residual %1 ps (%2 mm)</source>
        <translation> · 残差 %1 ps（%2 mm）</translation>
    </message>
    <message>
        <source> (forced in)</source>
        <translation>（强制纳入）</translation>
    </message>
    <message>
        <source> (forced out)</source>
        <translation>（强制剔除）</translation>
    </message>
    <message>
        <source> · station flag %1</source>
        <translation> · 测站标志 %1</translation>
    </message>
    <message>
        <source> · record %1</source>
        <translation> · 记录 %1</translation>
    </message>
    <message>
        <source> · row %1</source>
        <translation> · 行 %1</translation>
    </message>
    <message>
        <source>station flag 2 (%1)</source>
        <translation>测站标志 2（%1）</translation>
    </message>
    <message>
        <source>noise (%1)</source>
        <translation>噪声（%1）</translation>
    </message>
    <message>
        <source>signal (%1)</source>
        <translation>信号（%1）</translation>
    </message>
    <message>
        <source>recovered (%1)</source>
        <translation>恢复（%1）</translation>
    </message>
    <message>
        <source>rejected (%1)</source>
        <translation>剔除（%1）</translation>
    </message>
    <message>
        <source>post-fit band (%1)</source>
        <translation>后拟合带内（%1）</translation>
    </message>
    <message>
        <source>noise</source>
        <translation>噪声</translation>
    </message>
    <message>
        <source>rejected by the post-fit</source>
        <translation>被后拟合剔除</translation>
    </message>
    <message>
        <source>recovered</source>
        <translation>恢复</translation>
    </message>
    <message>
        <source>in the post-fit&apos;s band</source>
        <translation>位于后拟合带内</translation>
    </message>
    <message>
        <source>signal</source>
        <translation>信号</translation>
    </message>
    <message>
        <source>&lt;br&gt;(%1)</source>
        <translation>&lt;br&gt;（%1）</translation>
    </message>
    <message>
        <source>manual (%1)</source>
        <translation>人工（%1）</translation>
    </message>
    <message>
        <source>trend (zero)</source>
        <translation>趋势（零）</translation>
    </message>
    <message>
        <source>trend (deg %1, max %2)</source>
        <translation>趋势（%1 阶，最高 %2）</translation>
    </message>
    <message>
        <source>trend (degree %1)</source>
        <translation>趋势（%1 阶）</translation>
    </message>
    <message>
        <source>normal points (%1)</source>
        <translation>标准点（%1）</translation>
    </message>
    <message>
        <source>station normal points (%1)</source>
        <translation>测站标准点（%1）</translation>
    </message>
    <message>
        <source>O-C − trend (ps, two-way)</source>
        <translation>O-C − 趋势（ps，双程）</translation>
    </message>
    <message>
        <source>Residual about the post-fit trend</source>
        <translation>相对后拟合趋势的残差</translation>
    </message>
    <message>
        <source>O-C (no post-fit, so no residual view: %1)</source>
        <translation>O-C（未进行后拟合，无残差视图：%1）</translation>
    </message>
    <message>
        <source>O-C − track trend (ns)</source>
        <translation>O-C − 轨迹趋势 (ns)</translation>
    </message>
    <message>
        <source>5σ band (%1)</source>
        <translation>5σ 带（%1）</translation>
    </message>
    <message>
        <source>followed (%1)</source>
        <translation>所跟踪轨迹（%1）</translation>
    </message>
    <message>
        <source>No point kept by the post-fit</source>
        <translation>后拟合未保留任何点</translation>
    </message>
    <message>
        <source>No post-fit residuals: %1</source>
        <translation>无后拟合残差：%1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Accepted&lt;/b&gt; %1 of %2 (signal %3, recovered %4), post-fit kept %5, rejected %6&lt;br&gt;&lt;b&gt;RMS&lt;/b&gt; %7 ps (%8 mm one-way) · skew %9 · kurtosis %10 · peak−mean %11 ps&lt;br&gt;</source>
        <translation>&lt;b&gt;接受&lt;/b&gt; %1 / %2（信号 %3，恢复 %4），后拟合保留 %5，剔除 %6&lt;br&gt;&lt;b&gt;RMS&lt;/b&gt; %7 ps（单程 %8 mm）· 偏度 %9 · 峰度 %10 · 峰值−均值 %11 ps&lt;br&gt;</translation>
    </message>
    <message>
        <source>%1 more points within the post-fit&apos;s band (where the image stopped)&lt;br&gt;</source>
        <translation>另有 %1 个点位于后拟合带内（二值图像未及之处）&lt;br&gt;</translation>
    </message>
    <message>
        <source>Band narrowed by the noise beside it: ±%1 ps = %2 σ of the signal&apos;s %3 ps (best expected F1)&lt;br&gt;</source>
        <translation>带宽因旁侧噪声收窄：±%1 ps = 信号 %3 ps 的 %2 σ（期望 F1 最佳）&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Normal points&lt;/b&gt; %1 (bins of %2 s)</source>
        <translation>&lt;b&gt;标准点&lt;/b&gt; %1 个（分段长 %2 s）</translation>
    </message>
    <message>
        <source>&lt;b&gt;No normal points&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;无标准点&lt;/b&gt;：%1</translation>
    </message>
    <message>
        <source>&lt;b&gt;&lt;span style=&apos;color:#c05000&apos;&gt;Doubtful, no normal points&lt;/span&gt;&lt;/b&gt;: %1</source>
        <translation>&lt;b&gt;&lt;span style=&apos;color:#c05000&apos;&gt;存疑，无标准点&lt;/span&gt;&lt;/b&gt;：%1</translation>
    </message>
    <message>
        <source>&lt;br&gt;(also: %1)</source>
        <translation>&lt;br&gt;（另：%1）</translation>
    </message>
    <message>
        <source>&lt;b&gt;&lt;span style=&apos;color:#c05000&apos;&gt;Doubtful, no normal points&lt;/span&gt;&lt;/b&gt;: %1&lt;br&gt;</source>
        <translation>&lt;b&gt;&lt;span style=&apos;color:#c05000&apos;&gt;存疑，无标准点&lt;/span&gt;&lt;/b&gt;：%1&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Post-fit:&lt;/b&gt; %1&lt;br&gt;</source>
        <translation>&lt;b&gt;后拟合：&lt;/b&gt;%1&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Against the prediction&lt;/b&gt;: %1</source>
        <translation>&lt;br&gt;&lt;b&gt;与预报比较&lt;/b&gt;：%1</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;Scale&lt;/b&gt; mag_T %1 px/s, mag_OC %2 px/s, area ≥ %3 px, %4-connectivity%5 · C %6</source>
        <translation>&lt;br&gt;&lt;b&gt;尺度&lt;/b&gt; mag_T %1 px/s，mag_OC %2 px/s，面积 ≥ %3 px，%4 连通%5 · C %6</translation>
    </message>
    <message>
        <source> (automatic, kept while C moves)</source>
        <translation>（自动，调整 C 时保持不变）</translation>
    </message>
    <message>
        <source> (automatic)</source>
        <translation>（自动）</translation>
    </message>
    <message>
        <source>&lt;br&gt;Refined: screened again on the O-C less the accepted track&apos;s trend (%1 round(s); the search&apos;s scale, in the panel: mag_T %2 px/s, mag_OC %3 px/s)</source>
        <translation>&lt;br&gt;精化：在 O-C 减去已接受轨迹的趋势后重新筛选（%1 轮；面板中为搜索所用尺度：mag_T %2 px/s，mag_OC %3 px/s）</translation>
    </message>
    <message>
        <source>&lt;br&gt;%1 regions, %2 candidates, %3 on the line, %4 recovered · %5 ms</source>
        <translation>&lt;br&gt;%1 个区域，%2 个候选，%3 个在直线上，%4 个恢复 · %5 ms</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;No noise floor&lt;/b&gt;: a filtered pass (σ %1 ps); +%2 within 5σ</source>
        <translation>&lt;br&gt;&lt;b&gt;无噪声底&lt;/b&gt;：已滤波的过境（σ %1 ps）；5σ 内另有 +%2</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;b&gt;vs %1&lt;/b&gt;: precision %2, recall %3</source>
        <translation>&lt;br&gt;&lt;b&gt;对比 %1&lt;/b&gt;：精确率 %2，召回率 %3</translation>
    </message>
    <message>
        <source>simulation truth</source>
        <translation>模拟真值</translation>
    </message>
    <message>
        <source>station filter flags</source>
        <translation>测站滤波标志</translation>
    </message>
    <message>
        <source>undefined (nothing accepted)</source>
        <translation>未定义（无接受点）</translation>
    </message>
    <message>
        <source>slr.main_plot: &quot;%1&quot; is neither &quot;oc&quot; nor &quot;residual&quot;</source>
        <translation>slr.main_plot：&quot;%1&quot; 既不是 &quot;oc&quot; 也不是 &quot;residual&quot;</translation>
    </message>
    <message>
        <source>SLR manual edit of point %1: the pass has %2 points</source>
        <translation>点 %1 的 SLR 人工编辑：该过境只有 %2 个点</translation>
    </message>
    <message>
        <source>Open a ranging pass</source>
        <translation>打开测距过境</translation>
    </message>
    <message>
        <source>CRD and O-C tables (*.frd *.fr2 *.npt *.np2 *.crd *.csv);;All files (*)</source>
        <translation>CRD 与 O-C 表 (*.frd *.fr2 *.npt *.np2 *.crd *.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot open the file</source>
        <translation>无法打开该文件</translation>
    </message>
    <message>
        <source>%1 and %2: one station normal-point file at a time</source>
        <translation>%1 和 %2：一次只能使用一个测站标准点文件</translation>
    </message>
    <message>
        <source>%1: a station&apos;s normal points are compared with the full-rate pass they were formed from, and no pass is open: open the pass and this file together, or this file in the Station normal points tab of the open pass</source>
        <translation>%1：测站标准点需与生成它们的全速率过境进行比较，而当前未打开任何过境：请将该过境与此文件一起打开，或在已打开过境的“测站标准点”选项卡中打开此文件</translation>
    </message>
    <message>
        <source>%1 and %2: one %3 at a time</source>
        <translation>%1 和 %2：一次只能使用一个%3</translation>
    </message>
    <message>
        <source>prediction</source>
        <translation>预报</translation>
    </message>
    <message>
        <source>station file</source>
        <translation>测站文件</translation>
    </message>
    <message>
        <source>CRD file or O-C table…</source>
        <translation>CRD 文件或 O-C 表…</translation>
    </message>
    <message>
        <source>Hover	SLR ▸ one time cursor on the O-C plot, the binary image and the histogram</source>
        <translation>Hover	SLR ▸ 在 O-C 图、二值图像和直方图上显示同一时间光标</translation>
    </message>
    <message>
        <source>the prediction, which this pass did not use, is left out</source>
        <translation>该过境未使用的预报不包含在内</translation>
    </message>
    <message numerus="yes">
        <source>%n point(s) forced in or out by hand are not in the command</source>
        <translation>
            <numerusform>有 %n 个人工强制纳入或剔除的点未包含在命令中</numerusform>
        </translation>
    </message>
    <message>
        <source>SLR pass screening</source>
        <translation>SLR 过境筛选</translation>
    </message>
    <message>
        <source>a simulated kHz pass</source>
        <translation>模拟 kHz 过境</translation>
    </message>
    <message>
        <source>Tune from this file&apos;s passes…</source>
        <translation>按本文件的各过境调参…</translation>
    </message>
    <message>
        <source>The satellite&apos;s parameters chosen from the station&apos;s own filter flags (2 data, 1 noise) over every pass of the open CRD file; shown before they are applied</source>
        <translation>按测站自己的滤波标志（2 数据、1 噪声）在所打开 CRD 文件的每个过境上为该卫星选择参数；应用前先显示</translation>
    </message>
    <message>
        <source>Tune from this file&apos;s passes</source>
        <translation>按本文件的各过境调参</translation>
    </message>
    <message>
        <source>Open a CRD file whose filter flags hold the station&apos;s decisions (2 data, 1 noise) first.</source>
        <translation>请先打开一个其滤波标志记录了测站判定（2 数据、1 噪声）的 CRD 文件。</translation>
    </message>
    <message>
        <source>Tuning on the passes of %1…</source>
        <translation>正在按 %1 的各过境调参…</translation>
    </message>
    <message>
        <source>Parameters from the station&apos;s flags: %1</source>
        <translation>按测站标志选择的参数：%1</translation>
    </message>
    <message>
        <source>&lt;p&gt;%1 pass(es) of %2 screened with %3 candidates; the station&apos;s filter flags are the labels.&lt;/p&gt;</source>
        <translation>&lt;p&gt;%2 的 %1 个过境以 %3 组候选参数筛选；测站的滤波标志作为标签。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;The starting point stays&lt;/b&gt;: no candidate beats it by more than 0.001 without losing more than 0.002 on a pass.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;保持起始参数&lt;/b&gt;：没有候选参数在任一过境损失不超过 0.002 的前提下比它高出 0.001 以上。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;The starting point stays&lt;/b&gt;: the best candidate, %1 (mean F1 %2), does not hold out: the choices made without each pass in turn score %3 on the passes left out, the starting point %4.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;保持起始参数&lt;/b&gt;：最佳候选参数 %1（平均 F1 %2）未通过留一验证：依次留出每个过境、在其余过境上所作的选择，在留出的过境上得分 %3，起始参数为 %4。&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p&gt;Chosen: &lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;选定：&lt;b&gt;%1&lt;/b&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Pass</source>
        <translation>过境</translation>
    </message>
    <message>
        <source>Points (data)</source>
        <translation>点数（数据）</translation>
    </message>
    <message>
        <source>F1 now</source>
        <translation>当前 F1</translation>
    </message>
    <message>
        <source>F1 chosen</source>
        <translation>选定 F1</translation>
    </message>
    <message>
        <source>Held out</source>
        <translation>留出验证</translation>
    </message>
    <message>
        <source>mean</source>
        <translation>平均</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;i&gt;Held out: each pass scored with the choice made without it (leave one pass out).&lt;/i&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;i&gt;留出验证：每个过境用不含它所做的选择评分（留一过境法）。&lt;/i&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Apply to this pass</source>
        <translation>应用于本过境</translation>
    </message>
    <message>
        <source>Sets the chosen cosine constant, rejection and band in the parameters (one step: Edit ▸ Undo takes it back); Save as this satellite&apos;s preset keeps them</source>
        <translation>把选定的余弦常数、剔除倍数和带设入参数（一步操作：编辑 ▸ 撤销可还原）；“保存为该卫星的预设”可保留它们</translation>
    </message>
    <message>
        <source>The satellite&apos;s parameters chosen from the station&apos;s own filter flags over every pass of the open CRD file, as laserwb-cli slr tune chooses them</source>
        <translation>按测站自己的滤波标志在所打开 CRD 文件的每个过境上为该卫星选择参数，与 laserwb-cli slr tune 的选择相同</translation>
    </message>
    <message>
        <source>Tune from a folder&apos;s passes</source>
        <translation>由文件夹中的过境调参</translation>
    </message>
    <message>
        <source>Open a pass of the satellite to tune first: the folder&apos;s passes of that satellite are tuned on.</source>
        <translation>请先打开要调参卫星的一个过境：将用文件夹中该卫星的过境调参。</translation>
    </message>
    <message>
        <source>A folder of CRD files with the station&apos;s flags</source>
        <translation>含测站筛选标记的 CRD 文件所在文件夹</translation>
    </message>
    <message>
        <source>Tune from a folder&apos;s passes…</source>
        <translation>由文件夹中的过境调参…</translation>
    </message>
    <message>
        <source>The open satellite&apos;s parameters chosen from the station&apos;s own filter flags over every pass of it in the CRD files of a folder (a station&apos;s archive), as laserwb-cli slr tune FOLDER chooses them</source>
        <translation>以测站自身的筛选标记，在一个文件夹（测站归档）的 CRD 文件中该卫星的所有过境上选出其参数，与 laserwb-cli slr tune FOLDER 的选择相同</translation>
    </message>
</context>
<context>
    <name>lwb::ui::Workspace</name>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
</context>
<context>
    <name>schema</name>
    <message>
        <source>method</source>
        <translation>方法</translation>
    </message>
    <message>
        <source>centre method: gray centroid, TEFM (paper 001) or the Gaussian fit (paper 000 + Guo + LM)</source>
        <translation>中心提取方法：灰度质心、TEFM（文献 001）或高斯拟合（文献 000 + Guo + LM）</translation>
    </message>
    <message>
        <source>preset</source>
        <translation>预设</translation>
    </message>
    <message>
        <source>name of the verdict criteria the verdict values came from (wu2021, yao2021)</source>
        <translation>判定值所依据的判定准则名称（wu2021、yao2021）</translation>
    </message>
    <message>
        <source>size</source>
        <translation>尺寸</translation>
    </message>
    <message>
        <source>ROI side N cut around the spot</source>
        <translation>围绕光斑截取的 ROI 边长 N</translation>
    </message>
    <message>
        <source>size strict</source>
        <translation>严格尺寸</translation>
    </message>
    <message>
        <source>a frame smaller than roi.size is an error instead of a smaller ROI (--roi and --set roi.size turn it on)</source>
        <translation>帧小于 roi.size 时报错，而不是改用较小的 ROI（--roi 和 --set roi.size 会开启此项）</translation>
    </message>
    <message>
        <source>blob sigma</source>
        <translation>斑点 σ</translation>
    </message>
    <message>
        <source>spot scale of the blob search&apos;s matched filter (frames without --center)</source>
        <translation>斑点搜索匹配滤波器的光斑尺度（用于未给出 --center 的帧）</translation>
    </message>
    <message>
        <source>night below</source>
        <translation>夜间背景上限</translation>
    </message>
    <message>
        <source>background below this is a night shot (paper: 300-500 DN)</source>
        <translation>背景低于此值即为夜间影像（文献：300-500 DN）</translation>
    </message>
    <message>
        <source>weak below</source>
        <translation>弱噪声上限</translation>
    </message>
    <message>
        <source>day background below this is weak noise (paper 000: 4000 DN)</source>
        <translation>白天背景低于此值为弱噪声（文献 000：4000 DN）</translation>
    </message>
    <message>
        <source>strong above</source>
        <translation>强噪声下限</translation>
    </message>
    <message>
        <source>day background above this is strong noise (paper 000: 4500 DN)</source>
        <translation>白天背景高于此值为强噪声（文献 000：4500 DN）</translation>
    </message>
    <message>
        <source>clip sigma</source>
        <translation>截断 σ</translation>
    </message>
    <message>
        <source>upper clip, in robust sigma, that removes spot pixels from the background</source>
        <translation>上截断阈值（以稳健 σ 计），用于从背景中去除光斑像素</translation>
    </message>
    <message>
        <source>iterations</source>
        <translation>迭代次数</translation>
    </message>
    <message>
        <source>clipping passes</source>
        <translation>截断迭代轮数</translation>
    </message>
    <message>
        <source>threshold factor</source>
        <translation>阈值系数</translation>
    </message>
    <message>
        <source>threshold = background + factor x (peak - background); 1/e^2 = 0.1353 (paper 001 eq. 3)</source>
        <translation>阈值 = 背景 + 系数 × (峰值 - 背景)；1/e^2 = 0.1353（文献 001 式 3）</translation>
    </message>
    <message>
        <source>peak smooth</source>
        <translation>峰值平滑</translation>
    </message>
    <message>
        <source>odd box size smoothing the ROI before the peak is taken; 1 = raw</source>
        <translation>取峰值前对 ROI 做均值平滑的奇数窗口尺寸；1 = 不平滑</translation>
    </message>
    <message>
        <source>fill holes</source>
        <translation>填充孔洞</translation>
    </message>
    <message>
        <source>dark pixels enclosed by the domain belong to it</source>
        <translation>被该区域包围的暗像素归入该区域</translation>
    </message>
    <message>
        <source>opening radius</source>
        <translation>开运算半径</translation>
    </message>
    <message>
        <source>cut features narrower than 2r+1 px (roads) off the domain; 0 = off</source>
        <translation>从区域中切除窄于 2r+1 px 的地物（如道路）；0 = 关闭</translation>
    </message>
    <message>
        <source>min peak snr</source>
        <translation>最小峰值 SNR</translation>
    </message>
    <message>
        <source>(peak - background) / noise below this: no spot</source>
        <translation>(峰值 - 背景) / 噪声低于此值：无光斑</translation>
    </message>
    <message>
        <source>min pixels</source>
        <translation>最少像素数</translation>
    </message>
    <message>
        <source>a domain smaller than this: no spot</source>
        <translation>区域小于此值：无光斑</translation>
    </message>
    <message>
        <source>local look from</source>
        <translation>局部复查起点</translation>
    </message>
    <message>
        <source>peaks from this x min_peak_snr up get a second look against a ring around them (kept as faint, doubtful)</source>
        <translation>峰值达到此值 × min_peak_snr 及以上时，再对照其周围的环形区域复查一次（保留为弱光斑，判定存疑）</translation>
    </message>
    <message>
        <source>local snr floor</source>
        <translation>局部 SNR 下限</translation>
    </message>
    <message>
        <source>second look: the peak passes standing this x min_peak_snr ring sigma above the ring&apos;s median</source>
        <translation>复查：峰值高出环形区域中位数达到（此值 × min_peak_snr）倍环形区域 σ 即通过</translation>
    </message>
    <message>
        <source>texture snr</source>
        <translation>纹理 SNR</translation>
    </message>
    <message>
        <source>second look: or this many sigma of the ring&apos;s pixel-scale texture (neighbour differences / sqrt 2)</source>
        <translation>复查：或高出环形区域像素尺度纹理的此倍数 σ（相邻像素差 / √2）</translation>
    </message>
    <message>
        <source>ring inner px</source>
        <translation>环内半径（px）</translation>
    </message>
    <message>
        <source>inner radius of that ring</source>
        <translation>该环形区域的内半径</translation>
    </message>
    <message>
        <source>ring outer px</source>
        <translation>环外半径（px）</translation>
    </message>
    <message>
        <source>outer radius of that ring</source>
        <translation>该环形区域的外半径</translation>
    </message>
    <message>
        <source>second spot min separation px</source>
        <translation>第二光斑最小间距（px）</translation>
    </message>
    <message>
        <source>two peaks at least this far apart are two spots (the second-spot verdict)</source>
        <translation>相距至少此距离的两个峰值视为两个光斑（用于第二光斑判定）</translation>
    </message>
    <message>
        <source>subtract background</source>
        <translation>扣除背景</translation>
    </message>
    <message>
        <source>subtract the background before the gray centroid (the paper weights raw DN)</source>
        <translation>计算灰度质心前先扣除背景（文献使用原始 DN 加权）</translation>
    </message>
    <message>
        <source>background offset</source>
        <translation>背景偏移量</translation>
    </message>
    <message>
        <source>step 1 ground offset subtracted from the chip (paper 001: 2000 DN); null = the estimated background</source>
        <translation>第 1 步从影像块中扣除的地面偏移量（文献 001：2000 DN）；空值 = 使用估计的背景</translation>
    </message>
    <message>
        <source>estimated</source>
        <translation>估计值</translation>
    </message>
    <message>
        <source>step 2: T = factor x max(I - offset); 1/e^2</source>
        <translation>第 2 步：T = 系数 × max(I - 偏移量)；1/e^2</translation>
    </message>
    <message>
        <source>erosion size</source>
        <translation>腐蚀尺寸</translation>
    </message>
    <message>
        <source>step 3: odd side of the erosion neighbourhood D1; 1 = none</source>
        <translation>第 3 步：腐蚀邻域 D1 的奇数边长；1 = 不腐蚀</translation>
    </message>
    <message>
        <source>centroid on eroded</source>
        <translation>在腐蚀图像上求质心</translation>
    </message>
    <message>
        <source>step 5 weights: the eroded image (the paper&apos;s order) instead of the thresholded one</source>
        <translation>第 5 步权重：使用腐蚀后的图像（文献的顺序），而非阈值化后的图像</translation>
    </message>
    <message>
        <source>xy term</source>
        <translation>xy 项</translation>
    </message>
    <message>
        <source>add the f.xy column (tilt); false = the paper&apos;s system</source>
        <translation>加入 f.xy 列（倾斜）；关闭 = 文献的方程组</translation>
    </message>
    <message>
        <source>guo iterations</source>
        <translation>Guo 迭代次数</translation>
    </message>
    <message>
        <source>model-weighted passes after the first solve (0 = paper)</source>
        <translation>首次求解后按模型加权的迭代次数（0 = 文献做法）</translation>
    </message>
    <message>
        <source>lm</source>
        <translation>LM 精化</translation>
    </message>
    <message>
        <source>Levenberg-Marquardt refinement (false = paper / Guo only)</source>
        <translation>Levenberg-Marquardt（列文伯格–马夸尔特）精化（关闭 = 仅用文献 / Guo 方法）</translation>
    </message>
    <message>
        <source>lm max iterations</source>
        <translation>LM 最大迭代次数</translation>
    </message>
    <message>
        <source>LM iteration cap</source>
        <translation>LM 迭代次数上限</translation>
    </message>
    <message>
        <source>lm tolerance px</source>
        <translation>LM 容差（px）</translation>
    </message>
    <message>
        <source>LM stops when a step moves the centre less than this</source>
        <translation>单步中心移动量小于此值时 LM 停止</translation>
    </message>
    <message>
        <source>lm tolerance fraction</source>
        <translation>LM 相对容差</translation>
    </message>
    <message>
        <source>LM also stops when a step moves the centre less than this fraction of its uncertainty (uncertainty_px at the start), and takes that step; 0 = off</source>
        <translation>单步中心移动量小于其不确定度（初始为 uncertainty_px）的此比例时，LM 也会停止，并采纳该步；0 = 关闭</translation>
    </message>
    <message>
        <source>lm tolerance shape</source>
        <translation>LM 形状容差</translation>
    </message>
    <message>
        <source>LM stops only when the step also changes the amplitude and the shape by less than this fraction of their values</source>
        <translation>仅当该步对振幅和形状的改变量也小于其数值的此比例时，LM 才停止</translation>
    </message>
    <message>
        <source>lm max move px</source>
        <translation>LM 最大移动量（px）</translation>
    </message>
    <message>
        <source>LM results further than this from the log fit are not kept</source>
        <translation>与对数拟合结果相距超过此值的 LM 结果不予保留</translation>
    </message>
    <message>
        <source>lm max shape change</source>
        <translation>LM 最大形状变化</translation>
    </message>
    <message>
        <source>nor those whose major sigma or sigma1 x sigma2 changed by more than this factor</source>
        <translation>长轴 σ 或 σ1 × σ2 变化超过此倍数的结果也不保留</translation>
    </message>
    <message>
        <source>lm window sigmas</source>
        <translation>LM 窗口 σ 数</translation>
    </message>
    <message>
        <source>LM window half-width in major-axis sigma, photon-limited ground</source>
        <translation>LM 窗口半宽（以长轴 σ 计），用于光子噪声受限的地面</translation>
    </message>
    <message>
        <source>lm window sigmas textured</source>
        <translation>LM 窗口 σ 数（纹理地面）</translation>
    </message>
    <message>
        <source>LM window half-width in major-axis sigma, textured ground</source>
        <translation>LM 窗口半宽（以长轴 σ 计），用于有纹理的地面</translation>
    </message>
    <message>
        <source>textured ratio</source>
        <translation>纹理判定比</translation>
    </message>
    <message>
        <source>ground counts as textured when its sigma exceeds the photon + read sigma by this factor</source>
        <translation>地面 σ 超过光子噪声与读出噪声 σ 的此倍数时，视为有纹理地面</translation>
    </message>
    <message>
        <source>lm min half width</source>
        <translation>LM 最小半宽</translation>
    </message>
    <message>
        <source>LM window half-width lower bound</source>
        <translation>LM 窗口半宽下限</translation>
    </message>
    <message>
        <source>core fraction</source>
        <translation>核心比例</translation>
    </message>
    <message>
        <source>domain not peaked (brighter ground joined it): log fit again on the pixels joined to the peak above this fraction of the brightest domain pixel&apos;s height; 0 = moments at once</source>
        <translation>区域无明显峰值（较亮地面并入其中）时：对与峰值相连、且高于区域最亮像素高度此比例的像素重新做对数拟合；0 = 直接用矩估计</translation>
    </message>
    <message>
        <source>difference fit</source>
        <translation>差分拟合</translation>
    </message>
    <message>
        <source>textured ground: LM on neighbouring-pixel differences (whitens real ground&apos;s red spectrum)</source>
        <translation>纹理地面：对相邻像素差做 LM 拟合（使真实地面的红噪声谱白化）</translation>
    </message>
    <message>
        <source>lm window sigmas difference</source>
        <translation>LM 窗口 σ 数（差分拟合）</translation>
    </message>
    <message>
        <source>LM window half-width in major-axis sigma for the difference fit</source>
        <translation>差分拟合的 LM 窗口半宽（以长轴 σ 计）</translation>
    </message>
    <message>
        <source>uncertainty from ground</source>
        <translation>由地面估计不确定度</translation>
    </message>
    <message>
        <source>uncertainty_px from the shot&apos;s own ground: the fit&apos;s centre templates applied to the ground&apos;s autocovariance measured in the ROI plus photon and read noise; false = the quick estimate below</source>
        <translation>由影像自身的地面估计 uncertainty_px：将拟合的中心模板作用于 ROI 内实测的地面自协方差，并计入光子噪声与读出噪声；关闭 = 使用下方的快速估计</translation>
    </message>
    <message>
        <source>uncertainty scale</source>
        <translation>不确定度缩放</translation>
    </message>
    <message>
        <source>factor on the ground part of that uncertainty for fits with the Cauchy loss (the robust fit beats its linearisation; calibrated on one photograph, aero1)</source>
        <translation>采用柯西损失的拟合中，该不确定度地面部分的乘数（稳健拟合优于其线性化估计；基于一张照片 aero1 标定）</translation>
    </message>
    <message>
        <source>radius95 factor</source>
        <translation>95% 置信半径系数</translation>
    </message>
    <message>
        <source>radius95_px = this x uncertainty_px (a Gaussian error: 1.73; on real ground it is heavier-tailed; calibrated on aero1)</source>
        <translation>radius95_px = 此值 × uncertainty_px（高斯误差为 1.73；真实地面上误差拖尾更重；基于 aero1 标定）</translation>
    </message>
    <message>
        <source>uncertainty texture scale</source>
        <translation>不确定度纹理缩放</translation>
    </message>
    <message>
        <source>quick uncertainty (LM&apos;s stop; uncertainty_px when uncertainty_from_ground is off): texture shift scale after the difference fit</source>
        <translation>快速不确定度（用于 LM 停止判据；uncertainty_from_ground 关闭时即为 uncertainty_px）：差分拟合后的纹理偏移缩放系数</translation>
    </message>
    <message>
        <source>uncertainty texture scale pixel fit</source>
        <translation>不确定度纹理缩放（像素拟合）</translation>
    </message>
    <message>
        <source>the same after the pixel fit</source>
        <translation>同上，用于像素拟合之后</translation>
    </message>
    <message>
        <source>uncertainty deadband</source>
        <translation>不确定度死区</translation>
    </message>
    <message>
        <source>quick uncertainty: texture counts beyond (1 + this) x the photon part</source>
        <translation>快速不确定度：纹理部分超过光子部分的 (1 + 此值) 倍时才计入</translation>
    </message>
    <message>
        <source>noise weights</source>
        <translation>噪声加权</translation>
    </message>
    <message>
        <source>LM weights 1 / (photon + read + ground-texture variance)</source>
        <translation>LM 权重取 1 / (光子噪声 + 读出噪声 + 地面纹理方差)</translation>
    </message>
    <message>
        <source>robust loss</source>
        <translation>稳健损失</translation>
    </message>
    <message>
        <source>textured ground: Cauchy loss instead of least squares</source>
        <translation>纹理地面：用柯西损失代替最小二乘</translation>
    </message>
    <message>
        <source>robust scale</source>
        <translation>稳健尺度</translation>
    </message>
    <message>
        <source>Cauchy scale in residual sigma</source>
        <translation>柯西尺度（以残差 σ 计）</translation>
    </message>
    <message>
        <source>axis ratio</source>
        <translation>轴比</translation>
    </message>
    <message>
        <source>good spots have C = sigma_x / sigma_y in this range (paper 000: (1, 1.5)); null = not checked</source>
        <translation>合格光斑的 C = σ_x / σ_y 位于此范围内（文献 000：(1, 1.5)）；空值 = 不检查</translation>
    </message>
    <message>
        <source>major axis px</source>
        <translation>长轴（px）</translation>
    </message>
    <message>
        <source>full major axis at 1/e^2 (paper 000: (10, 18))</source>
        <translation>1/e^2 处的长轴全长（文献 000：(10, 18)）</translation>
    </message>
    <message>
        <source>tilt deg</source>
        <translation>倾角（°）</translation>
    </message>
    <message>
        <source>tilt of the x-near axis (paper 000: (-30, 30))</source>
        <translation>接近 x 方向的轴的倾角（文献 000：(-30, 30)）</translation>
    </message>
    <message>
        <source>eccentricity</source>
        <translation>偏心率</translation>
    </message>
    <message>
        <source>spot eccentricity (paper 001: 0.2-0.8)</source>
        <translation>光斑偏心率（文献 001：0.2-0.8）</translation>
    </message>
    <message>
        <source>mse max</source>
        <translation>MSE 上限</translation>
    </message>
    <message>
        <source>fit residual limit (paper 000 eq. 8, f normalised to unit sum); null = off</source>
        <translation>拟合残差上限（文献 000 式 8，f 归一化为总和为 1）；空值 = 关闭</translation>
    </message>
    <message>
        <source>off</source>
        <translation>关闭</translation>
    </message>
    <message>
        <source>max uncertainty px</source>
        <translation>最大不确定度（px）</translation>
    </message>
    <message>
        <source>a centre whose 1-sigma radial uncertainty (uncertainty_px) exceeds this is doubtful; null = off</source>
        <translation>1σ 径向不确定度（uncertainty_px）超过此值的中心判为存疑；空值 = 关闭</translation>
    </message>
    <message>
        <source>check edge</source>
        <translation>检查边缘</translation>
    </message>
    <message>
        <source>the spot&apos;s 1/e^2 ellipse must lie inside the ROI</source>
        <translation>光斑的 1/e^2 椭圆必须位于 ROI 之内</translation>
    </message>
    <message>
        <source>edge extent</source>
        <translation>边缘检查范围</translation>
    </message>
    <message>
        <source>the edge check uses the 1/e^2 ellipse times this (1.25: the 2.5 sigma ellipse)</source>
        <translation>边缘检查使用 1/e^2 椭圆乘以此倍数（1.25：即 2.5σ 椭圆）</translation>
    </message>
    <message>
        <source>check saturation</source>
        <translation>检查饱和</translation>
    </message>
    <message>
        <source>saturated spot pixels make a shot doubtful</source>
        <translation>光斑像素饱和时影像判为存疑</translation>
    </message>
    <message>
        <source>saturation max pixels</source>
        <translation>饱和像素上限</translation>
    </message>
    <message>
        <source>more saturated domain pixels than this: doubtful</source>
        <translation>区域内饱和像素多于此值：存疑</translation>
    </message>
    <message>
        <source>check second spot</source>
        <translation>检查第二光斑</translation>
    </message>
    <message>
        <source>a second separate peak makes a shot doubtful</source>
        <translation>出现另一个独立峰值时影像判为存疑</translation>
    </message>
    <message>
        <source>second spot fraction</source>
        <translation>第二光斑强度比</translation>
    </message>
    <message>
        <source>a separate peak this strong (of the main amplitude): doubtful</source>
        <translation>独立峰值达到此强度（相对主峰振幅）：存疑</translation>
    </message>
    <message>
        <source>gain e per dn</source>
        <translation>增益（e/DN）</translation>
    </message>
    <message>
        <source>camera gain, for photon noise weights and the Cramer-Rao bound</source>
        <translation>相机增益，用于光子噪声权重和克拉美-罗界</translation>
    </message>
    <message>
        <source>read noise e</source>
        <translation>读出噪声（e）</translation>
    </message>
    <message>
        <source>read noise (rms)</source>
        <translation>读出噪声（RMS）</translation>
    </message>
    <message>
        <source>saturation dn</source>
        <translation>饱和值（DN）</translation>
    </message>
    <message>
        <source>full scale (16383 for 14-bit data)</source>
        <translation>满量程（14 位数据为 16383）</translation>
    </message>
    <message>
        <source>arcsec per px</source>
        <translation>每像素角秒数（″/px）</translation>
    </message>
    <message>
        <source>pointing change per pixel (paper 001 LFC: 1.5 urad/px = 0.31 arcsec)</source>
        <translation>每像素对应的指向变化（文献 001 足印相机：1.5 µrad/px = 0.31″）</translation>
    </message>
    <message>
        <source>reject sigma</source>
        <translation>剔除 σ</translation>
    </message>
    <message>
        <source>iterative k-sigma rejection of shots within a month; 0 = off</source>
        <translation>对同月影像做迭代 kσ 剔除；0 = 关闭</translation>
    </message>
    <message>
        <source>min shots</source>
        <translation>最少影像数</translation>
    </message>
    <message>
        <source>months with fewer shots are left out</source>
        <translation>影像数少于此值的月份不参与统计</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>automatic mode: mag_t, mag_oc, area_limit and connectivity left at 0 (auto) are chosen from the data (multi-scale search)</source>
        <translation>自动模式：保持为 0（自动）的 mag_t、mag_oc、area_limit 和连通性将根据数据选取（多尺度搜索）</translation>
    </message>
    <message>
        <source>mag t</source>
        <translation>时间放大倍数 mag_T</translation>
    </message>
    <message>
        <source>pixels per second of epoch (paper: 10 conventional, 1 diffuse); 0 = auto</source>
        <translation>每秒历元对应的像素数（文献：常规测距 10，漫反射测距 1）；0 = 自动</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>mag oc</source>
        <translation>O-C 放大倍数 mag_OC</translation>
    </message>
    <message>
        <source>pixels per second of O-C (paper: 1e10 conventional, 1e7 diffuse); 0 = auto</source>
        <translation>每秒 O-C 对应的像素数（文献：常规测距 1e10，漫反射测距 1e7）；0 = 自动</translation>
    </message>
    <message>
        <source>area limit</source>
        <translation>面积阈值</translation>
    </message>
    <message>
        <source>regions with at least this area are candidates (step 3); 0 = auto</source>
        <translation>面积不小于此值的区域作为候选（第 3 步）；0 = 自动</translation>
    </message>
    <message>
        <source>connectivity</source>
        <translation>连通性</translation>
    </message>
    <message>
        <source>4 for high echo rates, 8 for low (paper 004); 0 = auto</source>
        <translation>回波率高时取 4，低时取 8（文献 004）；0 = 自动</translation>
    </message>
    <message>
        <source>cosine c</source>
        <translation>余弦常数 C</translation>
    </message>
    <message>
        <source>cosine constant C of the recovery step (paper 004 eq. 3: 0.9 &lt; C &lt; 1; smaller lets noise in)</source>
        <translation>恢复步骤的余弦常数 C（文献 004 式 3：0.9 &lt; C &lt; 1；取值越小越容易混入噪声）</translation>
    </message>
    <message>
        <source>slope neighbours</source>
        <translation>斜率近邻数</translation>
    </message>
    <message>
        <source>step 4: slopes from each candidate piece to its k nearest pieces</source>
        <translation>第 4 步：计算每个候选片段到其 k 个最近片段的斜率</translation>
    </message>
    <message>
        <source>slope bin deg</source>
        <translation>斜率分段宽度（°）</translation>
    </message>
    <message>
        <source>step 4: bin width of the line-angle histogram</source>
        <translation>第 4 步：直线角度直方图的分段宽度</translation>
    </message>
    <message>
        <source>slope peak fraction</source>
        <translation>斜率峰值比例</translation>
    </message>
    <message>
        <source>step 4: the dominant range is the run of bins holding at least this fraction of the peak</source>
        <translation>第 4 步：主导范围为计数不低于峰值此比例的连续分段</translation>
    </message>
    <message>
        <source>slope agree fraction</source>
        <translation>斜率一致比例</translation>
    </message>
    <message>
        <source>step 4: a candidate is on the line when this share of its slopes is in range (paper: 1/3)</source>
        <translation>第 4 步：候选的斜率中有此比例落在主导范围内时，判定其位于直线上（文献：1/3）</translation>
    </message>
    <message>
        <source>max slope range deg</source>
        <translation>最大斜率范围（°）</translation>
    </message>
    <message>
        <source>step 4: the dominant range is at most this wide</source>
        <translation>第 4 步：主导范围的宽度不超过此值</translation>
    </message>
    <message>
        <source>slope block regions</source>
        <translation>斜率分块片段数</translation>
    </message>
    <message>
        <source>step 4: pieces per time block with its own histogram (curved tracks); 0 = one histogram (paper)</source>
        <translation>第 4 步：每个时间块（单独统计直方图）包含的片段数（用于弯曲轨迹）；0 = 只用一个直方图（文献做法）</translation>
    </message>
    <message>
        <source>one histogram</source>
        <translation>单一直方图</translation>
    </message>
    <message>
        <source>piece rows</source>
        <translation>片段行数</translation>
    </message>
    <message>
        <source>steps 4-5: regions cut into pieces of this many rows; 0 = whole regions (paper)</source>
        <translation>第 4-5 步：将区域切分为每段此行数的片段；0 = 保持整个区域（文献做法）</translation>
    </message>
    <message>
        <source>recovery gap factor</source>
        <translation>恢复间隙系数</translation>
    </message>
    <message>
        <source>step 5: anchors at most this many typical spacings apart; 0 = no limit (paper)</source>
        <translation>第 5 步：相邻锚点间距最多为典型间距的此倍数；0 = 不限（论文设置）</translation>
    </message>
    <message>
        <source>area tolerance</source>
        <translation>面积容差</translation>
    </message>
    <message>
        <source>automatic area limit: share of pure-noise regions allowed to reach it</source>
        <translation>自动面积阈值：允许达到该阈值的纯噪声区域所占比例</translation>
    </message>
    <message>
        <source>auto max points</source>
        <translation>自动模式最大点数</translation>
    </message>
    <message>
        <source>automatic mode scores scales on at most this many points</source>
        <translation>自动模式最多用此数量的点对各尺度评分</translation>
    </message>
    <message>
        <source>refine rounds</source>
        <translation>精化轮数</translation>
    </message>
    <message>
        <source>screening rounds on the O-C flattened by the accepted track&apos;s trend (0 in the paper&apos;s fixed procedure)</source>
        <translation>在扣除已接受轨迹趋势后的 O-C 上进行的筛选轮数（论文固定流程中为 0）</translation>
    </message>
    <message>
        <source>sparse rate below</source>
        <translation>稀疏回波率阈值</translation>
    </message>
    <message>
        <source>passes with fewer returns per second get the sparse-pass ladders and refinement; 0 = always</source>
        <translation>每秒回波数低于此值的过境采用稀疏过境的阶梯参数与精化；0 = 始终采用</translation>
    </message>
    <message>
        <source>follow track</source>
        <translation>跟踪轨迹</translation>
    </message>
    <message>
        <source>sparse passes: follow the track from the accepted pieces (ends, gaps, pieces beyond gaps)</source>
        <translation>稀疏过境：从已接受的片段出发跟踪轨迹（两端、间隙及间隙之外的片段）</translation>
    </message>
    <message>
        <source>accept floorless</source>
        <translation>接受无噪底过境</translation>
    </message>
    <message>
        <source>a pass with no noise floor (filtered; robust sigma &lt;= 1 ns, &lt;= 2 % beyond 5 sigma) keeps every point within 5 sigma of its track</source>
        <translation>无噪声底的过境（已滤波；稳健 σ &lt;= 1 ns，超出 5σ 的点 &lt;= 2 %）保留距其轨迹 5σ 以内的全部点</translation>
    </message>
    <message>
        <source>refraction</source>
        <translation>大气折射</translation>
    </message>
    <message>
        <source>tropospheric delay: Mendes &amp; Pavlis (2004) zenith delay with the FCULa mapping, from the pass&apos;s type-20 meteorological records (a warning and none without them); none leaves the whole delay in the O-C</source>
        <translation>对流层延迟：采用 Mendes &amp; Pavlis (2004) 天顶延迟与 FCULa 映射函数，由该过境的 20 型气象记录计算（无此记录时给出警告并不改正）；不改正时全部延迟保留在 O-C 中</translation>
    </message>
    <message>
        <source>wavelength nm</source>
        <translation>波长 (nm)</translation>
    </message>
    <message>
        <source>laser wavelength for the refraction; null = the record&apos;s C0 configuration, else 532 with a warning</source>
        <translation>用于折射改正的激光波长；null = 取记录中 C0 配置的值，若无则取 532 并给出警告</translation>
    </message>
    <message>
        <source>from the record</source>
        <translation>取自记录</translation>
    </message>
    <message>
        <source>shapiro</source>
        <translation>夏皮罗延迟</translation>
    </message>
    <message>
        <source>add the relativistic (Shapiro) light-time delay of the Earth&apos;s field (a few mm)</source>
        <translation>加入地球引力场引起的相对论（夏皮罗）光行时延迟（几毫米）</translation>
    </message>
    <message>
        <source>centre of mass offset m</source>
        <translation>质心偏移 (m)</translation>
    </message>
    <message>
        <source>centre of mass to reflector, one way; null = the CPF&apos;s H5 value when its positions are of the centre of mass (H2 flag 0), else 0</source>
        <translation>卫星质心至反射器的单程距离；null = 当 CPF 位置为质心位置（H2 标志为 0）时取其 H5 值，否则为 0</translation>
    </message>
    <message>
        <source>from the CPF</source>
        <translation>取自 CPF</translation>
    </message>
    <message>
        <source>convergence s</source>
        <translation>收敛阈值 (s)</translation>
    </message>
    <message>
        <source>the light-time iteration stops when a leg changes by less than this</source>
        <translation>单程光行时变化小于此值时停止光行时迭代</translation>
    </message>
    <message>
        <source>max iterations</source>
        <translation>最大迭代次数</translation>
    </message>
    <message>
        <source>light-time iterations per leg</source>
        <translation>每个单程的光行时迭代次数</translation>
    </message>
    <message>
        <source>lagrange points</source>
        <translation>拉格朗日节点数</translation>
    </message>
    <message>
        <source>Lagrange nodes of the CPF interpolation (ILRS practice: 8-10 for LEO at 1-5 min steps)</source>
        <translation>CPF 插值的拉格朗日节点数（ILRS 惯例：低轨卫星 1-5 分钟步长时取 8-10）</translation>
    </message>
    <message>
        <source>cpf direction</source>
        <translation>CPF 方向</translation>
    </message>
    <message>
        <source>which CPF position records: 0 the common epoch, 1 or 2 for files that have them</source>
        <translation>使用哪类 CPF 位置记录：0 为公共历元，1 或 2 用于包含此类记录的文件</translation>
    </message>
    <message>
        <source>own trend degree</source>
        <translation>自身趋势阶数</translation>
    </message>
    <message>
        <source>without a prediction: degree of the robust polynomial of the squared time of flight (lowered for short passes: max((records-1)/4, 2))</source>
        <translation>无预报时：飞行时间平方的稳健多项式阶数（短过境时降低：max((记录数-1)/4, 2)）</translation>
    </message>
    <message>
        <source>own trend huber k</source>
        <translation>自身趋势 Huber k</translation>
    </message>
    <message>
        <source>without a prediction: the trend&apos;s Huber constant, in robust standard deviations</source>
        <translation>无预报时：趋势的 Huber 常数，以稳健标准差为单位</translation>
    </message>
    <message>
        <source>own trend max iterations</source>
        <translation>自身趋势最大迭代次数</translation>
    </message>
    <message>
        <source>without a prediction: the trend&apos;s reweighting iterations</source>
        <translation>无预报时：趋势的重加权迭代次数</translation>
    </message>
    <message>
        <source>own trend min points</source>
        <translation>自身趋势最少点数</translation>
    </message>
    <message>
        <source>without a prediction: fewer usable records is an error</source>
        <translation>无预报时：可用记录少于此数即报错</translation>
    </message>
    <message>
        <source>degree</source>
        <translation>阶数</translation>
    </message>
    <message>
        <source>trend polynomial degree (Legendre, per segment); the largest tried when auto_degree</source>
        <translation>趋势多项式阶数（勒让德多项式，逐段）；启用 auto_degree 时为尝试的最高阶数</translation>
    </message>
    <message>
        <source>auto degree</source>
        <translation>自动定阶</translation>
    </message>
    <message>
        <source>choose each segment&apos;s model by BIC (degrees 0..degree, cubic splines); false = degree as given</source>
        <translation>按 BIC 为每段选择模型（0..degree 阶多项式、三次样条）；false = 使用给定阶数</translation>
    </message>
    <message>
        <source>split gap s</source>
        <translation>分段间隙 (s)</translation>
    </message>
    <message>
        <source>split the trend at gaps longer than this; 0 = auto (3 bin lengths, at least 20 s); &lt; 0 = one trend</source>
        <translation>在长于此值的间隙处将趋势分段；0 = 自动（3 个分段长度，至少 20 s）；&lt; 0 = 单一趋势</translation>
    </message>
    <message>
        <source>gross sigma</source>
        <translation>粗差 σ</translation>
    </message>
    <message>
        <source>reject points this many robust sigma off the local track before the fit; 0 = off</source>
        <translation>拟合前剔除偏离局部轨迹超过此倍数稳健 σ 的点；0 = 关闭</translation>
    </message>
    <message>
        <source>k of the k-sigma rejection: 2.5 single-photon, 3 multi-photon (ILRS); 0 = off</source>
        <translation>k 倍 σ 剔除中的 k：单光子取 2.5，多光子取 3（ILRS）；0 = 关闭</translation>
    </message>
    <message>
        <source>noise band</source>
        <translation>噪声带</translation>
    </message>
    <message>
        <source>narrow the k-sigma band where the noise beside the track is measurable: the band of the best expected F1 (the signal&apos;s sigma with that noise taken out), never wider than k sigma</source>
        <translation>在轨迹旁的噪声可测时收窄 k 倍 σ 带：取期望 F1 最佳的带宽（信号的 σ 扣除该噪声后求得），不宽于 k 倍 σ</translation>
    </message>
    <message>
        <source>take band</source>
        <translation>带内取点</translation>
    </message>
    <message>
        <source>take the points the screening left out that lie within the final band about the trend (inside its segments), and fit again with them</source>
        <translation>将筛选遗漏、但位于趋势最终带内（各分段范围内）的点纳入，并据此重新拟合</translation>
    </message>
    <message>
        <source>fit-reject iterations</source>
        <translation>拟合-剔除迭代次数</translation>
    </message>
    <message>
        <source>bin length s</source>
        <translation>分段长度 (s)</translation>
    </message>
    <message>
        <source>normal-point bin length; 0 = from the altitude (ILRS table)</source>
        <translation>标准点分段长度；0 = 按卫星高度确定（ILRS 表）</translation>
    </message>
    <message>
        <source>from altitude</source>
        <translation>按高度确定</translation>
    </message>
    <message>
        <source>altitude km</source>
        <translation>卫星高度 (km)</translation>
    </message>
    <message>
        <source>satellite altitude for the normal-point bin; 0 = unknown (from the pass when it can be)</source>
        <translation>用于确定标准点分段的卫星高度；0 = 未知（尽可能由过境数据求得）</translation>
    </message>
    <message>
        <source>min points</source>
        <translation>最少点数</translation>
    </message>
    <message>
        <source>points a bin needs for a normal point; 0 = ILRS minimum (6 by day, 3 by night)</source>
        <translation>一个分段形成标准点所需的点数；0 = ILRS 最小值（白天 6，夜间 3）</translation>
    </message>
    <message>
        <source>ILRS minimum</source>
        <translation>ILRS 最小值</translation>
    </message>
    <message>
        <source>day night</source>
        <translation>白天/夜间</translation>
    </message>
    <message>
        <source>day or night for the ILRS minimum of points per normal-point bin (6 by day, 3 by night): auto = from the Sun at the station bin by bin when the station is known (SINEX), else the day minimum</source>
        <translation>按白天或夜间确定每个标准点分段的 ILRS 最少点数（白天 6，夜间 3）：auto = 已知测站（SINEX）时逐段按测站处的太阳位置判断，否则取白天的最小值</translation>
    </message>
    <message>
        <source>fire rate hz</source>
        <translation>发射频率 (Hz)</translation>
    </message>
    <message>
        <source>laser fire rate for the normal points&apos; return rate; 0 = unknown</source>
        <translation>用于计算标准点回波率的激光发射频率；0 = 未知</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>normal points</source>
        <translation>标准点</translation>
    </message>
    <message>
        <source>form normal points (off: trend and statistics only)</source>
        <translation>生成标准点（关闭时仅计算趋势与统计量）</translation>
    </message>
    <message>
        <source>model</source>
        <translation>模型</translation>
    </message>
    <message>
        <source>fitted surface: elliptical (7 parameters), circular (5), or auto (elliptical from 10 measurements)</source>
        <translation>拟合曲面：椭圆（7 个参数）、圆（5 个参数）或自动（测量值达 10 个时用椭圆）</translation>
    </message>
    <message>
        <source>noise</source>
        <translation>噪声</translation>
    </message>
    <message>
        <source>energy noise: estimated from the array (data) or rel_noise and noise_floor as given</source>
        <translation>能量噪声：由阵列数据估计，或采用给定的 rel_noise 与 noise_floor</translation>
    </message>
    <message>
        <source>fit background</source>
        <translation>拟合背景</translation>
    </message>
    <message>
        <source>fit the background; false holds it at detector.background</source>
        <translation>拟合背景；false 时固定为 detector.background</translation>
    </message>
    <message>
        <source>background</source>
        <translation>背景</translation>
    </message>
    <message>
        <source>the background held fixed when fit_background is false</source>
        <translation>fit_background 为 false 时固定使用的背景值</translation>
    </message>
    <message>
        <source>trigger</source>
        <translation>触发阈值</translation>
    </message>
    <message>
        <source>energies at or below this count as untriggered; 0 = no threshold</source>
        <translation>能量小于等于此值视为未触发；0 = 无阈值</translation>
    </message>
    <message>
        <source>saturation</source>
        <translation>饱和阈值</translation>
    </message>
    <message>
        <source>energies at or above this count as saturated; 0 = from the flags or a clipped maximum</source>
        <translation>能量大于等于此值视为饱和；0 = 依据标志位或截顶的最大值判断</translation>
    </message>
    <message>
        <source>rel noise</source>
        <translation>相对噪声</translation>
    </message>
    <message>
        <source>given noise: sigma as a fraction of the energy</source>
        <translation>给定噪声：σ 占能量的比例</translation>
    </message>
    <message>
        <source>noise floor</source>
        <translation>噪声底</translation>
    </message>
    <message>
        <source>given noise: additive sigma</source>
        <translation>给定噪声：加性 σ</translation>
    </message>
    <message>
        <source>censor</source>
        <translation>截尾处理</translation>
    </message>
    <message>
        <source>saturated and untriggered detectors enter the fit as bounds (false: set aside)</source>
        <translation>饱和与未触发的探测器作为界限参与拟合（false：排除）</translation>
    </message>
    <message>
        <source>outlier sigma</source>
        <translation>粗差 σ</translation>
    </message>
    <message>
        <source>set aside detectors more than this many robust sigma off; 0 = off (plain least squares)</source>
        <translation>排除偏差超过此倍数稳健 σ 的探测器；0 = 关闭（普通最小二乘）</translation>
    </message>
    <message>
        <source>scale chi2</source>
        <translation>按 χ² 缩放</translation>
    </message>
    <message>
        <source>given noise: scale the covariance by the reduced chi-square</source>
        <translation>给定噪声：按约化 χ² 缩放协方差</translation>
    </message>
    <message>
        <source>recommended detectors</source>
        <translation>推荐探测器数</translation>
    </message>
    <message>
        <source>warn below this many detectors seeing the footprint (paper 002: 9)</source>
        <translation>观测到足印的探测器少于此数时给出警告（论文 002：9）</translation>
    </message>
    <message>
        <source>Levenberg-Marquardt accepted steps</source>
        <translation>Levenberg-Marquardt 接受步数</translation>
    </message>
    <message>
        <source>chi2 probability</source>
        <translation>χ² 概率</translation>
    </message>
    <message>
        <source>given noise: doubtful when chi-square is this improbable (either tail)</source>
        <translation>给定噪声：χ² 的概率低于此值（任一尾）时判定为存疑</translation>
    </message>
    <message>
        <source>max axis ratio</source>
        <translation>最大轴比</translation>
    </message>
    <message>
        <source>doubtful when the fitted footprint&apos;s axis ratio exceeds this</source>
        <translation>拟合足印的轴比超过此值时判定为存疑</translation>
    </message>
    <message>
        <source>each beam on its own (single), or beam 2 = beam 1 rotated by dR(r, a, b) (dual)</source>
        <translation>各波束独立解算（single），或波束 2 = 波束 1 经 dR(r, a, b) 旋转（dual）</translation>
    </message>
    <message>
        <source>solve range</source>
        <translation>解算距离偏差</translation>
    </message>
    <message>
        <source>solve the range biases (false: pointing only)</source>
        <translation>解算距离偏差（false：仅解算指向）</translation>
    </message>
    <message>
        <source>fix relative</source>
        <translation>固定相对旋转</translation>
    </message>
    <message>
        <source>dual model: hold the relative rotation at its design</source>
        <translation>双波束模型：相对旋转固定为设计值</translation>
    </message>
    <message>
        <source>sigma h</source>
        <translation>水平 σ</translation>
    </message>
    <message>
        <source>default control-point sigma per horizontal axis</source>
        <translation>控制点每个水平轴的默认 σ</translation>
    </message>
    <message>
        <source>sigma v</source>
        <translation>高程 σ</translation>
    </message>
    <message>
        <source>default control-point height sigma (RTK: 0.05 or less)</source>
        <translation>控制点默认高程 σ（RTK：0.05 或更小）</translation>
    </message>
    <message>
        <source>sigma range</source>
        <translation>测距 σ</translation>
    </message>
    <message>
        <source>range noise per shot</source>
        <translation>每发激光的测距噪声</translation>
    </message>
    <message>
        <source>sigma attitude urad</source>
        <translation>姿态 σ (µrad)</translation>
    </message>
    <message>
        <source>attitude noise per axis per shot</source>
        <translation>每发激光每个轴的姿态噪声</translation>
    </message>
    <message>
        <source>sigma orbit</source>
        <translation>轨道 σ</translation>
    </message>
    <message>
        <source>orbit position noise per axis</source>
        <translation>每个轴的轨道位置噪声</translation>
    </message>
    <message>
        <source>scale the covariance by the reduced chi-square</source>
        <translation>按约化 χ² 缩放协方差</translation>
    </message>
    <message>
        <source>accepted Levenberg-Marquardt steps</source>
        <translation>Levenberg-Marquardt 接受的迭代步数</translation>
    </message>
    <message>
        <source>min rcond</source>
        <translation>最小倒条件数</translation>
    </message>
    <message>
        <source>below this reciprocal condition the geometry is singular</source>
        <translation>倒条件数低于此值时视为几何奇异</translation>
    </message>
    <message>
        <source>sample interval ns</source>
        <translation>采样间隔 (ns)</translation>
    </message>
    <message>
        <source>sample interval of waveform files without a time column (GF-7: 0.5)</source>
        <translation>无时间列的波形文件的采样间隔（GF-7：0.5）</translation>
    </message>
    <message>
        <source>smooth ns</source>
        <translation>平滑 (ns)</translation>
    </message>
    <message>
        <source>Gaussian smoothing for the peak search only</source>
        <translation>仅用于峰值搜索的高斯平滑</translation>
    </message>
    <message>
        <source>min separation ns</source>
        <translation>最小峰间距 (ns)</translation>
    </message>
    <message>
        <source>smallest peak distance looked for</source>
        <translation>搜索的最小峰间距</translation>
    </message>
    <message>
        <source>min second peak</source>
        <translation>次峰最小比例</translation>
    </message>
    <message>
        <source>the weaker peak must reach this fraction of the stronger</source>
        <translation>较弱峰须达到较强峰的此比例</translation>
    </message>
    <message>
        <source>incidence deg</source>
        <translation>入射角 (°)</translation>
    </message>
    <message>
        <source>beam incidence from the vertical</source>
        <translation>波束相对铅垂方向的入射角</translation>
    </message>
    <message>
        <source>thred h</source>
        <translation>高度阈值 thred_h</translation>
    </message>
    <message>
        <source>height threshold thred_h of the feature match (paper 002: 0.1)</source>
        <translation>特征匹配的高度阈值 thred_h（论文 002：0.1）</translation>
    </message>
    <message>
        <source>dn min</source>
        <translation>DN 下限</translation>
    </message>
    <message>
        <source>camera linear range, lower end (paper 003: 100)</source>
        <translation>相机线性范围下限（论文 003：100）</translation>
    </message>
    <message>
        <source>dn max</source>
        <translation>DN 上限</translation>
    </message>
    <message>
        <source>camera linear range, upper end (paper 003: 60000)</source>
        <translation>相机线性范围上限（论文 003：60000）</translation>
    </message>
    <message>
        <source>exclude out of range</source>
        <translation>排除超范围区域</translation>
    </message>
    <message>
        <source>leave regions whose mean DN is outside the linear range out of the fit (else: warn)</source>
        <translation>平均 DN 超出线性范围的区域不参与拟合（否则仅警告）</translation>
    </message>
    <message>
        <source>vm pct</source>
        <translation>光谱仪不确定度 V_M (%)</translation>
    </message>
    <message>
        <source>spectrometer uncertainty V_M (paper 003: 0.17)</source>
        <translation>光谱仪不确定度 V_M（论文 003：0.17）</translation>
    </message>
    <message>
        <source>mask out of range pixels</source>
        <translation>掩膜超范围像素</translation>
    </message>
    <message>
        <source>measured regions: pixels outside the linear range are masked from the mean (false: only counted)</source>
        <translation>测量区域：超出线性范围的像素不计入均值（false：仅统计个数）</translation>
    </message>
    <message>
        <source>min region pixels</source>
        <translation>区域最少像素数</translation>
    </message>
    <message>
        <source>pixels a measured region keeps after masking, else it is left out of the fit</source>
        <translation>测量区域掩膜后须保留的像素数，否则不参与拟合</translation>
    </message>
    <message>
        <source>min region fraction</source>
        <translation>区域最小像素比例</translation>
    </message>
    <message>
        <source>and this fraction of its pixels</source>
        <translation>且须保留其像素的此比例</translation>
    </message>
    <message>
        <source>nan out of range</source>
        <translation>超范围置为 NaN</translation>
    </message>
    <message>
        <source>reflectance image: pixels outside the range become NaN</source>
        <translation>反射率影像：超出范围的像素置为 NaN</translation>
    </message>
    <message>
        <source>uncertainty image</source>
        <translation>不确定度影像</translation>
    </message>
    <message>
        <source>also compute the per-pixel uncertainty image</source>
        <translation>同时计算逐像素不确定度影像</translation>
    </message>
    <message>
        <source>limit pct</source>
        <translation>误差限 (%)</translation>
    </message>
    <message>
        <source>relative-error limit of the check regions (paper 003: 5)</source>
        <translation>检查区域的相对误差限（论文 003：5）</translation>
    </message>
    <message>
        <source>features</source>
        <translation>特征点</translation>
    </message>
    <message>
        <source>keypoints: akaze (sub-pixel) or orb (faster, about 0.5 px)</source>
        <translation>特征点：akaze（亚像素精度）或 orb（更快，约 0.5 px）</translation>
    </message>
    <message>
        <source>max features</source>
        <translation>最大特征点数</translation>
    </message>
    <message>
        <source>ORB keypoints per frame</source>
        <translation>每帧 ORB 特征点数</translation>
    </message>
    <message>
        <source>ratio test</source>
        <translation>比值检验</translation>
    </message>
    <message>
        <source>Lowe&apos;s ratio for the two nearest descriptors</source>
        <translation>两个最近邻描述子的 Lowe 比值</translation>
    </message>
    <message>
        <source>transform between neighbouring frames</source>
        <translation>相邻帧之间的变换</translation>
    </message>
    <message>
        <source>ransac px</source>
        <translation>RANSAC 阈值 (px)</translation>
    </message>
    <message>
        <source>RANSAC inlier distance</source>
        <translation>RANSAC 内点距离阈值</translation>
    </message>
    <message>
        <source>min inliers</source>
        <translation>最少内点数</translation>
    </message>
    <message>
        <source>fewer consistent matches for a pair is an error</source>
        <translation>一对帧的一致匹配少于此数即报错</translation>
    </message>
    <message>
        <source>max rotation deg</source>
        <translation>最大旋转角 (°)</translation>
    </message>
    <message>
        <source>warn above this rotation between neighbours</source>
        <translation>相邻帧间旋转超过此值时警告</translation>
    </message>
    <message>
        <source>max scale change</source>
        <translation>最大尺度变化</translation>
    </message>
    <message>
        <source>warn above this relative scale change between neighbours</source>
        <translation>相邻帧间相对尺度变化超过此值时警告</translation>
    </message>
    <message>
        <source>blend</source>
        <translation>融合方式</translation>
    </message>
    <message>
        <source>overlaps: feathered weights, plain mean, or the earliest frame</source>
        <translation>重叠区：羽化加权、简单平均或取最早的帧</translation>
    </message>
    <message>
        <source>max canvas pixels</source>
        <translation>画布最大像素数</translation>
    </message>
    <message>
        <source>larger mosaics are refused (memory)</source>
        <translation>超过此大小的拼接图将被拒绝（内存限制）</translation>
    </message>
    <message>
        <source>image -&gt; map transform</source>
        <translation>影像 -&gt; 地图变换</translation>
    </message>
    <message>
        <source>collinear tolerance</source>
        <translation>共线容差</translation>
    </message>
    <message>
        <source>GCPs count as collinear below this spread across / along their best line</source>
        <translation>控制点垂直于/沿其最佳拟合直线的分布比低于此值时视为共线</translation>
    </message>
    <message>
        <source>outlier p</source>
        <translation>粗差概率 p</translation>
    </message>
    <message>
        <source>chance that a sound GCP is named an outlier: one the transform of the others misses by more than this allows (and 0.5 px) is named, and the map doubtful</source>
        <translation>正常控制点被判为粗差的概率：若由其余控制点求得的变换对某点的偏差超过此概率所允许的范围（且超过 0.5 px），则该点判为粗差，地图判定为存疑</translation>
    </message>
    <message>
        <source>pixel size m</source>
        <translation>像元大小 (m)</translation>
    </message>
    <message>
        <source>map pixel size; 0 = the image&apos;s own scale</source>
        <translation>地图像元大小；0 = 采用影像自身比例尺</translation>
    </message>
    <message>
        <source>roi</source>
        <translation>感兴趣区域</translation>
    </message>
    <message>
        <source>segment</source>
        <translation>分割</translation>
    </message>
    <message>
        <source>gcm</source>
        <translation>灰度质心法</translation>
    </message>
    <message>
        <source>tefm</source>
        <translation>椭圆拟合（TEFM）</translation>
    </message>
    <message>
        <source>gauss</source>
        <translation>高斯拟合</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>判定</translation>
    </message>
    <message>
        <source>camera</source>
        <translation>相机</translation>
    </message>
    <message>
        <source>screen</source>
        <translation>信号筛选</translation>
    </message>
    <message>
        <source>oc</source>
        <translation>O-C 计算</translation>
    </message>
    <message>
        <source>postfit</source>
        <translation>后拟合</translation>
    </message>
    <message>
        <source>detector</source>
        <translation>探测器阵列</translation>
    </message>
    <message>
        <source>pointing</source>
        <translation>指向与测距定标</translation>
    </message>
    <message>
        <source>waveform</source>
        <translation>波形匹配</translation>
    </message>
    <message>
        <source>mosaic</source>
        <translation>拼接</translation>
    </message>
    <message>
        <source>gcp</source>
        <translation>几何校正（控制点）</translation>
    </message>
</context>
</TS>
