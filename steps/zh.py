"""Chinese values in Chinese step phrasings (`# language: zh-CN` features): the step library's functions take
the English values the driver interface knows, so a Chinese sentence's words are converted first."""
from __future__ import annotations

import re
from typing import Callable

# How a Chinese sentence lists things: 、 ， , ; and the words 和/及 ("CPU3、MDM8和TXC").
LIST_SEP = re.compile(r"\s*(?:[、,，;；]|和|及)\s*")


def words(table: dict[str, str]) -> Callable[[str], str]:
    """A converter: a Chinese word of `table` becomes its English value; anything else (English, numbers)
    passes unchanged, so the Chinese sentence also takes the English values."""
    def convert(word: str) -> str:
        return table.get(word, word)
    return convert


def listing(text: str) -> str:
    """CPU3、MDM8和TXC -> CPU3, MDM8, TXC; 120、137和137.5 -> 120, 137, 137.5 (the lists steps read);
    English lists are left as they are."""
    return LIST_SEP.sub(", ", text)

DIRECTIONS = {"前进": "forward", "向前": "forward", "后退": "reverse", "向后": "reverse", "中立": "neutral",
              "零位": "neutral"}
FRAMES = {"状态": "status", "命令": "command", "令牌": "token", "块": "block"}


direction = words(DIRECTIONS)
frame = words(FRAMES)


# -- steps/atp.py (CTCS-2 200C on-board ATP) --------------------------------------------------------------
ATP_LINES = {"上行": "up", "下行": "down", "上": "up", "下": "down"}
ATP_MODES = {"完全监控": "FS", "完全": "FS", "部分监控": "PS", "部分": "PS", "待机": "SB", "机车信号": "CS",
             "休眠": "SL", "自动驾驶": "AM"}
# The brakes an ATP commands (its `ATP brake` output: none, max service, emergency). No word for a plain service
# brake (常用 -> service): an ATP never commands one, so such a feature could never pass; 最大常用 is the word.
ATP_BRAKES = {"最大常用": "max service", "紧急": "emergency", "无": "no"}
ATP_PERMISSIONS = {"门控许可": "door enable", "开门许可": "door enable", "门允许": "door enable",
                   "屏蔽门许可": "PSD permission", "屏蔽门开关许可": "PSD permission", "站台门许可": "PSD permission",
                   "ATO允许": "ATO allowed"}
ATP_DMI_TEXTS = {"CFSK故障": "CFSK fault", "载频不一致": "carrier inconsistent", "默认报文": "default telegram",
                 "应答器信息错误": "balise information error", "DEF故障": "DEF fault"}
ATP_REACTIONS = {"无反应": "none", "无": "none", "最大常用制动": "max service", "最大常用": "max service"}
ATP_RECORD_FIELDS = {"低频码": "code", "低频信息": "code", "载频": "carrier", "信号幅度": "amplitude",
                     "幅度": "amplitude", "运行状态": "state", "状态": "state", "轨道电路类型": "type", "类型": "type"}
ATP_RECORD_VALUES = {"正常": "ok", "故障": "fault"}


# 上行/下行 -> up/down (a carrier set, the line direction of a balise group).
atp_line = words(ATP_LINES)
atp_mode = words(ATP_MODES)


def atp_brake(word: str | None) -> str:
    """The brake the ATP commands: 最大常用 -> max service, ...; no word at all (ATP不输出制动) -> no."""
    return "no" if word is None else ATP_BRAKES.get(word, word)


atp_permission = words(ATP_PERMISSIONS)
atp_dmi_text = words(ATP_DMI_TEXTS)
atp_reaction = words(ATP_REACTIONS)


def atp_record_fields(text: str) -> str:
    """低频码LU、载频2300 Hz、信号幅度420 mV、状态正常和轨道电路类型ZPW-2000A -> code LU, carrier 2300, ...;
    a list without a Chinese field name is returned unchanged."""
    items = LIST_SEP.split(text.strip())
    if not any(item.startswith(tuple(ATP_RECORD_FIELDS)) for item in items):
        return text
    out = []
    for item in items:
        key = max((k for k in ATP_RECORD_FIELDS if item.startswith(k)), key=len, default=None)
        if key is None:
            out.append(item)
            continue
        value = item[len(key):].strip().replace(" ", "")
        if ATP_RECORD_FIELDS[key] == "carrier" and value.endswith("Hz"):
            value = value[:-2]
        out.append(f"{ATP_RECORD_FIELDS[key]} {ATP_RECORD_VALUES.get(value, value)}")
    return ", ".join(out)


# -- steps/vdx.py (the VDX emergency-brake interface) ---------------------------------------------------------
VDX_FIRMWARES = {"旧版": "old", "旧": "old", "新版": "new", "新": "new"}
VDX_STATES = {"断开": "open", "闭合": "closed", "得电": "energised", "励磁": "energised", "失电": "de-energised",
              "失磁": "de-energised"}


vdx_firmware = words(VDX_FIRMWARES)
# 断开/闭合 (the emergency-brake loop), 得电/失电 (a relay) -> open/closed, energised/de-energised.
vdx_state = words(VDX_STATES)


vdx_volts = listing


# -- steps/vehicle.py, monitor.py, network.py, train.py (core library) ---------------------------------------
# Vehicle outputs and inputs (sut/reference/crh2/vehicle.py catalogue): one Chinese word names one English value,
# so "断开" is always open (VCB, contactor) and a light or an air conditioner is 开启/关断, never 打开/关闭.
CORE_STATES = {
    "得电": "energised", "励磁": "energised", "失电": "de-energised", "失磁": "de-energised",
    "缓解": "released", "释放": "released", "施加": "applied", "有指令": "commanded", "无指令": "not commanded",
    "动作": "acting", "关闭": "closed", "闭合": "closed", "打开": "open", "断开": "open",
    "允许": "permitted", "封锁": "blocked", "使能": "enabled",
    "空闲": "idle", "已预告": "warned", "过分相中": "passing", "等待手动进入": "awaiting manual entry",
    "等待手动恢复": "awaiting manual restore", "手动过分相中": "manual passing",
    "运行": "running", "停止": "stopped", "无": "none", "下一站": "next station", "欢迎乘车": "welcome aboard",
    "升起": "up", "降下": "down", "自供电": "own", "扩展供电": "extended", "无供电": "none",
    "开启": "on", "关断": "off", "投入": "in", "切除": "cut out",
    "连挂": "coupled", "分离": "separated", "正常": "normal", "油温过高": "over-temperature", "过温": "over-temperature",
    "一次绕组过流": "primary overcurrent", "二次绕组过流": "secondary overcurrent",
    "三次绕组过流": "tertiary overcurrent", "二次绕组接地": "secondary earth fault",
    "三次绕组接地": "tertiary earth fault", "严重故障": "severe fault", "预告信号故障": "warning signal fault",
    "手动恢复": "manual restore", "复位": "reset",
}
# The Chinese state words as a regex alternative (longest first), for the parsers.re output steps.
CORE_STATE_RE = "|".join(sorted(CORE_STATES, key=len, reverse=True))
CORE_SWITCH = {"ON": "on", "OFF": "off", "接通": "on", "断开": "off", "合": "on", "断": "off"}
CORE_BRAKES = {"常用": "service", "紧急": "emergency"}
CORE_SIGNALS = {"预告": "warning", "进入": "entry", "通过": "exit", "退出": "exit"}
CORE_EVENTS = {"故障": "failed", "失效": "failed", "恢复": "recovered", "修复": "recovered"}
CORE_MEDIA = {"光纤": "fibre", "双绞线": "twisted-pair"}


# 断开 -> open, 失电 -> de-energised, 分离 -> separated, ...; anything else (English, numbers) unchanged.
core_state = words(CORE_STATES)
# A switch position: 接通/ON -> on, 断开/OFF -> off.
core_switch = words(CORE_SWITCH)
core_brake = words(CORE_BRAKES)
# A neutral-section signal: 预告/进入/通过 -> warning/entry/exit.
core_signal = words(CORE_SIGNALS)
core_event = words(CORE_EVENTS)
core_medium = words(CORE_MEDIA)


core_list = listing


# -- steps/metro.py (metro TCN profile), steps/environment.py, steps/extra_*.py -----------------------------
# The display unit's modes as a Chinese feature names them, to the form's message identifiers (sut/contract/
# form.yaml, metro-tcn texts); the step compares the SUT's declared text of the identifier, as the ATP's DMI
# does (steps/atp.py): the SUT's own words are never assumed. And the MVB data classes (sut/codecs/mvb.py).
METRO_MODES = {"正常": "normal", "正常模式": "normal", "无主控司机室": "no cab", "列车网络故障": "train network failure",
               "紧急运行": "emergency operation", "紧急运行模式": "emergency operation"}
METRO_DATA_CLASSES = {"过程数据": "process data", "消息数据": "message data", "信息数据": "message data",
                      "监视数据": "supervisory data", "监管数据": "supervisory data"}


# The event texts the metro steps look for on the displays and in the records, as a Chinese feature writes
# them, to the message identifiers of sut/contract/form.yaml (metro-tcn texts). <name> is a name the sentence
# fills in (car4.VVVF, unit1.MVB, A); a bare text without names stands for any (不显示"无状态数据").
METRO_TEXTS = {"<device>:无状态数据": "<device>: no status data", "无状态数据": "no status data",
               "<device>:恢复应答": "<device>: answering again", "恢复应答": "answering again",
               "<node>:WTB无应答": "<node>: no answer on WTB", "WTB无应答": "no answer on WTB",
               "<node>:WTB恢复应答": "<node>: answering on WTB again", "WTB恢复应答": "answering on WTB again",
               "WTB主站切换(<node>无响应)": "WTB master (<node> silent)", "输入取自<module>": "inputs from <module>",
               "无可用MVB I/O模块": "no MVB I/O module alive",
               "<bus>线路<line>故障": "<bus> line <line>: fault", "<bus>线路<line>恢复": "<bus> line <line>: restored",
               "列车网络故障:制动停车": "train network failure: braking to a stop"}


def patterns(table: dict[str, str]) -> Callable[[str], str]:
    """A converter for texts with names in them: a text that fills in a Chinese pattern of `table` (its <name>
    placeholders standing for ASCII names, full-width and ASCII colons and brackets alike) becomes the English
    pattern with the same names; anything else passes unchanged."""
    def regex(pattern: str) -> re.Pattern:
        parts = re.split(r"<([\w-]+)>", _halfwidth(pattern))
        return re.compile("".join(re.escape(part) if i % 2 == 0 else f"(?P<{part}>[A-Za-z0-9_.]+)"
                                  for i, part in enumerate(parts)))
    compiled = [(regex(chinese), english) for chinese, english in table.items()]

    def convert(text: str) -> str:
        plain = _halfwidth(text.strip())
        for rx, english in compiled:
            found = rx.fullmatch(plain)
            if found:
                return re.sub(r"<([\w-]+)>", lambda p: found.group(p.group(1)), english)
        return text
    return convert


def _halfwidth(text: str) -> str:
    return text.translate(str.maketrans("：（），", ":(),"))


# 正常 -> normal, 列车网络故障 -> train network failure, 紧急运行 -> emergency operation.
metro_mode = words(METRO_MODES)
# car4.VVVF:无状态数据 -> car4.VVVF: no status data, unit1.MVB线路B故障 -> unit1.MVB line B: fault.
metro_text = patterns(METRO_TEXTS)
metro_switch = words({"接通": "on", "断开": "off"})      # a switch's two positions


def metro_data_classes(text: str) -> str:
    """过程数据和监视数据 -> process data, supervisory data (the list the MVB master-frame step reads);
    a list without a Chinese data-class name is returned unchanged."""
    items = [i for i in LIST_SEP.split(text.strip()) if i]
    if not any(i in METRO_DATA_CLASSES for i in items):
        return text
    return ", ".join(METRO_DATA_CLASSES.get(i, i) for i in items)


# -- steps/monitor.py, network.py, extra_display.py, extra_records.py, extra_control.py: the CRH2 cab monitor --
# The CRH2 cab monitor's texts as a Chinese feature writes them, to the message identifiers of
# sut/contract/form.yaml (crh2 texts): the fault texts it shows (CRH2_FAULTS) and the lines of its maintenance
# view (CRH2_RECORDS; 故障 of a record is the event "failed", as in CORE_EVENTS). <name> is a name the sentence
# fills in (car3.LCU, car5.LCU.MDM9, unit1); a bare name or the words of an identifier pass unchanged.
CRH2_FAULTS = {"<node>无状态数据": "no status data from <node>", "无状态数据": "no status data from",
               "<node>与<neighbour>之间光传输故障": "optical transmission fault between <node> and <neighbour>",
               "<node>与<neighbour>间光传输故障": "optical transmission fault between <node> and <neighbour>",
               "<board>故障": "<board> failure", "<unit>:主电路保护动作": "<unit>: main circuit protection acted",
               "制动力不足": "insufficient brake force",
               "过分相:严重故障,手动过分相": "neutral section: severe fault, pass manually",
               "过分相:预告信号故障,强制自动过分相": "neutral section: warning signal fault, forced automatic passing",
               "过分相:无进入信号,手动进入": "neutral section: no entry signal, enter manually",
               "过分相:无退出信号,手动恢复": "neutral section: no exit signal, restore manually"}
RESTART_REASONS = {"过温": "over-temperature", "低温": "under-temperature", "过压": "overvoltage",
                   "欠压": "undervoltage", "断电": "interruption", "耐压试验": "withstand test"}
CRH2_RECORDS = {"<board>故障": "<board> failed", "<board>恢复": "<board> recovered",
                "<node>电源重启": "<node>.supply restarted",
                **{f"<node>电源因{zh}重启": f"<node>.supply restarted after {en}" for zh, en in RESTART_REASONS.items()}}


# car6.LCU无状态数据 -> no status data from car6.LCU, car5.LCU.MDM9故障 -> car5.LCU.MDM9 failure.
crh2_fault = patterns(CRH2_FAULTS)
# car3.LCU.MDM9故障 -> car3.LCU.MDM9 failed, car3.LCU电源因低温重启 -> car3.LCU.supply restarted after under-temperature.
crh2_record = patterns(CRH2_RECORDS)
