# bash completion for laserwb-cli (installed as share/bash-completion/completions/laserwb-cli).
# Commands and kinds are listed here; each command's options are read from its own --help, and
# the keys of --set from --help-params, so the completion follows the program it completes.

_laserwb_cli() {
    local cur prev words cword
    if declare -F _init_completion >/dev/null; then
        _init_completion || return
    else
        cur=${COMP_WORDS[COMP_CWORD]}; prev=${COMP_WORDS[COMP_CWORD-1]}
        words=("${COMP_WORDS[@]}"); cword=$COMP_CWORD
    fi
    local prog=${words[0]}
    local commands="footprint trend slr crd simulate eval bench calib radiometry demo version help"
    if [[ $cword -eq 1 ]]; then
        COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
        return
    fi
    local cmd=${words[1]} sub=""
    case $cmd in
        simulate) [[ $cword -eq 2 ]] && { COMPREPLY=($(compgen -W "footprint trend slr calib radiometry" -- "$cur")); return; } ; sub=${words[2]} ;;
        eval)     [[ $cword -eq 2 ]] && { COMPREPLY=($(compgen -W "footprint" -- "$cur")); return; } ; sub=${words[2]} ;;
        bench)    [[ $cword -eq 2 ]] && { COMPREPLY=($(compgen -W "footprint slr" -- "$cur")); return; } ; sub=${words[2]} ;;
        calib)    [[ $cword -eq 2 ]] && { COMPREPLY=($(compgen -W "detector waveform pointing stats" -- "$cur")); return; } ; sub=${words[2]} ;;
        crd)      [[ $cword -eq 2 ]] && { COMPREPLY=($(compgen -W "check" -- "$cur")); return; } ; sub=${words[2]} ;;
        radiometry) [[ $cword -eq 2 ]] && { COMPREPLY=($(compgen -W "mosaic gcp fit apply check" -- "$cur")); return; } ; sub=${words[2]} ;;
    esac
    case $prev in
        --set)
            # KEY= from the command's parameter table ("  key = default ...")
            local keys
            keys=$("$prog" $cmd $sub --help-params 2>/dev/null | sed -n 's/^ *\([a-z_][a-z0-9_.]*\) = .*/\1=/p')
            compopt -o nospace 2>/dev/null
            COMPREPLY=($(compgen -W "$keys" -- "$cur"))
            return ;;
        --out-dir) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    esac
    # An option whose --help line gives its values ("--connectivity 4|8", "--preset wu2021|yao2021",
    # "[--kind khz|conventional|...]"): those values, not file names.
    if [[ $prev == --* ]]; then
        local choices
        choices=$("$prog" $cmd $sub --help 2>/dev/null |
                  grep -o -- "${prev} [A-Za-z0-9_.+-]*\(|[A-Za-z0-9_.+-]*\)\+" | head -1 | cut -d' ' -f2)
        if [[ -n $choices ]]; then
            COMPREPLY=($(compgen -W "${choices//|/ }" -- "$cur"))
            return
        fi
    fi
    if [[ $cur == -* ]]; then
        local opts
        opts=$("$prog" $cmd $sub --help 2>/dev/null | grep -o -- '--[a-z][a-z0-9-]*' | sort -u)
        COMPREPLY=($(compgen -W "$opts -o -q" -- "$cur"))
        return
    fi
    COMPREPLY=($(compgen -f -- "$cur"))
    compopt -o filenames 2>/dev/null
}
complete -F _laserwb_cli laserwb-cli

_laserwb() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}
    case $prev in
        --workspace) COMPREPLY=($(compgen -W "footprint footprint:trend slr calibration calibration:waveform radiometry" -- "$cur")); return ;;
    esac
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "--help --version --screenshot --workspace --size" -- "$cur"))
        return
    fi
    COMPREPLY=($(compgen -f -- "$cur"))
    compopt -o filenames 2>/dev/null
}
complete -F _laserwb laserwb
