package io.concord.agents.control;

/**
 * What stands in for a task's phase for a while: the chair drives elsewhere ({@link StepAside}) or
 * stands until a new plan comes ({@link Replanning}), and then the phase it interrupted
 * ({@link #resume}) goes on toward its goal. An idle chair's {@link GoingHome} interrupts no
 * phase: it ends with the chair idle where it parked. While an interruption is under way, the
 * task's state stays that of the phase it interrupted.
 */
abstract sealed class Interruption extends Phase permits MakingWay, Replanning {
    /** The phase that goes on afterwards, or null (an idle chair). */
    final Phase resume;

    Interruption(Phase resume) {
        super(resume == null ? null : resume.task);
        this.resume = resume;
    }

    /** True while a plan is asked for and not yet answered: the chair stands. */
    abstract boolean awaitsPlan();

    @Override
    final boolean drives() {
        return !awaitsPlan();
    }

    /** The goal of the phase it interrupted (-1 for an idle chair's). */
    @Override
    final int goal() {
        return resume == null ? -1 : resume.goal();
    }
}
