import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.AchieveREResponder;
import jade.proto.SSContractNetResponder;
import jade.proto.SSResponderDispatcher;
import jade.proto.SimpleAchieveREResponder;

/**
 * Three responders: a SimpleAchieveREResponder for "square" requests, an AchieveREResponder whose
 * result step is a registered behaviour (registerPrepareResultNotification) for "cube" requests,
 * and single-session contract-net responders made by an SSResponderDispatcher for CFPs.
 */
public class Server extends Agent {
    @Override
    protected void setup() {
        MessageTemplate req = AchieveREResponder.createMessageTemplate(FIPANames.InteractionProtocol.FIPA_REQUEST);
        addBehaviour(new SimpleAchieveREResponder(this, MessageTemplate.and(req, MessageTemplate.MatchOntology("square"))) {
            @Override
            protected ACLMessage prepareResponse(ACLMessage request) throws NotUnderstoodException, RefuseException {
                int n = Integer.parseInt(request.getContent());
                if (n < 0) {
                    throw new RefuseException("negative");
                }
                ACLMessage agree = request.createReply();
                agree.setPerformative(ACLMessage.AGREE);
                return agree;
            }

            @Override
            protected ACLMessage prepareResultNotification(ACLMessage request, ACLMessage response) throws FailureException {
                int n = Integer.parseInt(request.getContent());
                ACLMessage inform = request.createReply();
                inform.setPerformative(ACLMessage.INFORM);
                inform.setContent(Integer.toString(n * n));
                return inform;
            }
        });

        AchieveREResponder cube = new AchieveREResponder(this, MessageTemplate.and(req, MessageTemplate.MatchOntology("cube"))) {
            @Override
            protected ACLMessage prepareResponse(ACLMessage request) {
                return null;
            }
        };
        cube.registerPrepareResultNotification(new OneShotBehaviour(this) {
            @Override
            public void action() {
                ACLMessage request = (ACLMessage) getDataStore().get(cube.REQUEST_KEY);
                int n = Integer.parseInt(request.getContent());
                ACLMessage inform = request.createReply();
                inform.setPerformative(ACLMessage.INFORM);
                inform.setContent(Integer.toString(n * n * n));
                getDataStore().put(cube.RESULT_NOTIFICATION_KEY, inform);
                System.out.println("server: the registered step made the cube of " + n);
            }
        });
        addBehaviour(cube);

        MessageTemplate haggles = MessageTemplate.and(MessageTemplate.MatchProtocol(FIPANames.InteractionProtocol.FIPA_ITERATED_CONTRACT_NET),
                MessageTemplate.MatchPerformative(ACLMessage.CFP));
        addBehaviour(new SSResponderDispatcher(this, haggles) {
            @Override
            protected Behaviour createResponder(ACLMessage cfp) {
                return new jade.proto.SSIteratedContractNetResponder(myAgent, cfp) {
                    private int price = 12;

                    @Override
                    protected ACLMessage handleCfp(ACLMessage cfp) {
                        System.out.println("server: round for " + cfp.getContent());
                        ACLMessage propose = cfp.createReply();
                        propose.setPerformative(ACLMessage.PROPOSE);
                        propose.setContent(Integer.toString(price));
                        price -= 3;
                        return propose;
                    }

                    @Override
                    protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) {
                        ACLMessage inform = accept.createReply();
                        inform.setPerformative(ACLMessage.INFORM);
                        inform.setContent("bread for " + propose.getContent());
                        return inform;
                    }
                };
            }
        });

        MessageTemplate cfps = MessageTemplate.and(MessageTemplate.MatchProtocol(FIPANames.InteractionProtocol.FIPA_CONTRACT_NET),
                MessageTemplate.MatchPerformative(ACLMessage.CFP));
        addBehaviour(new SSResponderDispatcher(this, cfps) {
            @Override
            protected Behaviour createResponder(ACLMessage cfp) {
                System.out.println("server: a responder for " + cfp.getConversationId());
                return new SSContractNetResponder(myAgent, cfp) {
                    @Override
                    protected ACLMessage handleCfp(ACLMessage cfp) throws RefuseException {
                        if (cfp.getContent().equals("gold")) {
                            throw new RefuseException("no gold here");
                        }
                        ACLMessage propose = cfp.createReply();
                        propose.setPerformative(ACLMessage.PROPOSE);
                        propose.setContent(cfp.getContent() + " for 10");
                        return propose;
                    }

                    @Override
                    protected ACLMessage handleAcceptProposal(ACLMessage cfp, ACLMessage propose, ACLMessage accept) {
                        ACLMessage inform = accept.createReply();
                        inform.setPerformative(ACLMessage.INFORM);
                        inform.setContent("sold " + cfp.getContent());
                        return inform;
                    }

                    @Override
                    protected void handleRejectProposal(ACLMessage cfp, ACLMessage propose, ACLMessage reject) {
                        System.out.println("server: rejected for " + cfp.getContent());
                    }
                };
            }
        });
    }
}
