package jade.wrapper.gateway;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.core.behaviours.SequentialBehaviour;
import jade.util.Logger;

/**
 * The agent {@link JadeGateway} runs commands with: each command handed over by
 * {@code JadeGateway.execute} goes to {@link #processCommand} on the agent's thread, and the
 * caller waits until {@link #releaseCommand} is called with it. By default a command that is a
 * {@link Behaviour} is run by the agent and released when it ends (as JADE's); any other command
 * is logged as unknown and not released (override {@code processCommand} for your own commands).
 */
public class GatewayAgent extends Agent {
    private static final long serialVersionUID = 1L;
    private final Logger log = Logger.getMyLogger(getClass().getName());

    public GatewayAgent() {
        super();
    }

    /** Runs a Behaviour command and releases it when it ends; logs any other command as unknown. */
    protected void processCommand(Object command) {
        if (command instanceof Behaviour b) {
            SequentialBehaviour run = new SequentialBehaviour(this);
            run.addSubBehaviour(b);
            run.addSubBehaviour(new OneShotBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    releaseCommand(command);
                }
            });
            addBehaviour(run);
        } else {
            log.log(Logger.WARNING, "Unknown command " + command + ": override processCommand to run it");
        }
    }

    /** Tells the caller of {@code JadeGateway.execute} that the command is done. */
    public final void releaseCommand(Object command) {
        JadeGateway.released(command);
    }

    /** Takes the commands {@link JadeGateway} hands over (O2A) and passes each to {@link #processCommand}. */
    @Override
    protected void setup() {
        setEnabledO2ACommunication(true, 0);
        addBehaviour(new CyclicBehaviour(this) {
            private static final long serialVersionUID = 1L;

            @Override
            public void action() {
                Object command = myAgent.getO2AObject();
                if (command == null) {
                    block();
                    return;
                }
                processCommand(command);
            }
        });
    }
}
